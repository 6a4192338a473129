//! Scene files (TOML): camera, OBJ/glTF/built-in geometry with optional
//! material overrides, emissive meshes, point/spot/IES
//! lights, the primary light of the VPL application, and render settings.
//! Paths are relative to the scene file. Unknown keys and bad values are
//! errors that name the key and the line.
//!
//! ```toml
//! [camera]
//! position = [0.278, 0.273, -0.8]
//! look_at = [0.278, 0.273, 0.0]
//! fov = 39.3                       # vertical, degrees; `up` defaults to +y
//!
//! [[geometry]]
//! builtin = "cornell"              # or "cornell-glossy", "sphere" (unit, smooth); or obj = "room.obj", or gltf = "room.glb"
//! scale = 1.0
//! translate = [0, 0, 0]
//! emission_scale = 1.0             # 0 switches this geometry's emitters off
//! # Replaces the geometry's materials (glTF metallic-roughness; defaults shown):
//! material = { base_color = [0.8, 0.8, 0.8], metallic = 0.0, roughness = 0.5, ior = 1.5, specular = 1.0, emission = [0, 0, 0] }
//!
//! [[emissive_mesh]]
//! obj = "../../shared/data/meshes/bunny.obj"
//! emission = [4.0, 4.0, 4.0]
//! scale = 1.5
//! translate = [0.28, 0.0, 0.28]
//! subdivide = 0                    # each level splits every triangle into 4
//!
//! [[scatter_lights]]              # small triangle lights over the surfaces above
//! count = 10000
//! size = 0.012                     # edge length
//! offset = 0.002                   # above the surface, on the room's side
//! emission = [0.5, 0.45, 0.4]
//! seed = 1
//! face = "away"                    # or "surface" (toward it), "random"
//!
//! [[light_cloud]]                 # many point/spot/IES lights placed by a seed (every key: `light_cloud`'s docs)
//! count = 2000
//! placement = "volume"
//! intensity = [0.01, 0.01, 0.01]
//!
//! [[light]]
//! type = "ies"                     # or "point", "spot"
//! file = "../../shared/data/ies/indoor-60w-120deg.ies"
//! position = [0.278, 0.5, 0.279]
//! tint = [0.001, 0.001, 0.001]     # candela → scene intensity units and colour
//! nadir = [0.0, -1.0, 0.0]         # the profile's vertical angle 0 (default shown)
//! reference = [1.0, 0.0, 0.0]      # its horizontal angle 0 (default shown)
//!
//! [primary]
//! type = "spot"                    # or "directional" (direction, irradiance)
//! position = [0.278, 0.548, 0.2795]
//! direction = [0.0, -1.0, 0.0]
//! intensity = [0.232, 0.164, 0.055]
//! outer = 79.2                     # degrees; `inner` defaults to 0
//!
//! [render]
//! width = 512
//! height = 512
//! vpls = 65536
//! method = "slc"
//! error_bound = 0.008             # the VPL frame's ε
//! pt_error_bound = "auto"         # the path tracer's: a number, "auto" or "auto:C"
//! range = 0.1                      # method "clamp"'s range R
//! seed = 1
//! exposure = 1.0
//! ```

use crate::SceneError;
use crate::error_bound::BoundArg;
use crate::gltf::GltfScene;
use crate::light_cloud::LightCloudDef;
use crate::placement::{Stream, Surfaces};
use crate::scene::{Camera, Material, PrimaryLight, Scene};
use crate::shapes::{subdivide, subdivide_normals};
use glam::Vec3;
use serde::Deserialize;
use slc_core::LightError;
use slc_core::ies::IesProfile;
use slc_core::light::{IesLight, Light, PointLight, SpotLight};
use std::path::{Path, PathBuf};
use std::sync::Arc;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    camera: Option<CameraDef>,
    #[serde(default)]
    geometry: Vec<GeometryDef>,
    #[serde(default)]
    emissive_mesh: Vec<EmissiveDef>,
    #[serde(default)]
    scatter_lights: Vec<ScatterDef>,
    #[serde(default)]
    light_cloud: Vec<LightCloudDef>,
    #[serde(default)]
    light: Vec<LightDef>,
    primary: Option<LightDef>,
    #[serde(default)]
    render: RenderSettings,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CameraDef {
    position: [f32; 3],
    look_at: [f32; 3],
    #[serde(default = "up")]
    up: [f32; 3],
    #[serde(default = "fov")]
    fov: f32,
}

fn up() -> [f32; 3] {
    [0.0, 1.0, 0.0]
}
fn fov() -> f32 {
    39.3
}
fn one() -> f32 {
    1.0
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct GeometryDef {
    builtin: Option<String>,
    obj: Option<PathBuf>,
    gltf: Option<PathBuf>,
    /// Replaces every material of this geometry.
    material: Option<MaterialDef>,
    #[serde(default = "one")]
    scale: f32,
    #[serde(default)]
    translate: [f32; 3],
    /// Scales the emission of this geometry's materials (0 switches its
    /// emitters off, e.g. the Cornell box's ceiling light).
    #[serde(default = "one")]
    emission_scale: f32,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct EmissiveDef {
    obj: PathBuf,
    emission: [f32; 3],
    #[serde(default)]
    subdivide: u32,
    #[serde(default = "one")]
    scale: f32,
    #[serde(default)]
    translate: [f32; 3],
}

/// `material = { ... }` of a `[[geometry]]`: glTF's metallic-roughness
/// material (base colour, metallic, perceptual roughness), its dielectric's
/// IOR and `KHR_materials_specular` factor (0: a Lambertian dielectric),
/// and emission.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MaterialDef {
    #[serde(default = "grey")]
    base_color: [f32; 3],
    #[serde(default)]
    metallic: f32,
    #[serde(default = "half")]
    roughness: f32,
    #[serde(default = "ior")]
    ior: f32,
    #[serde(default = "one")]
    specular: f32,
    #[serde(default)]
    emission: [f32; 3],
}

fn grey() -> [f32; 3] {
    [0.8; 3]
}
fn half() -> f32 {
    0.5
}
fn ior() -> f32 {
    1.5
}

impl MaterialDef {
    fn material(&self) -> Result<Material, String> {
        if !(self.ior.is_finite() && self.ior >= 1.0) {
            return Err(format!("material: ior {} must be finite and >= 1", self.ior));
        }
        if !(0.0..=1.0).contains(&self.specular) {
            return Err(format!("material: specular {} must be in [0, 1]", self.specular));
        }
        let f0 = ((self.ior - 1.0) / (self.ior + 1.0)).powi(2) * self.specular;
        let m = Material {
            f0: Vec3::splat(f0),
            f90: self.specular,
            emission: v3(self.emission),
            ..Material::gltf(v3(self.base_color), self.metallic, self.roughness)
        };
        m.validate(0)
            .map_err(|e| e.to_string().replace("invalid scene: material 0: ", "material: "))?;
        Ok(m)
    }
}

/// `[[scatter_lights]]`: `count` small equilateral triangle lights of edge
/// `size`, scattered uniformly by area over the non-emissive surfaces
/// defined so far, `offset` above them on their front side (the side
/// their winding's normal points to), emitting `emission` away from the
/// surface, toward it (`face = "surface"`) or any way (`face = "random"`);
/// placed by `seed`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ScatterDef {
    count: u32,
    size: f32,
    #[serde(default)]
    offset: f32,
    emission: [f32; 3],
    #[serde(default = "one_u32")]
    seed: u32,
    #[serde(default)]
    face: Face,
}

/// Which way a `[[scatter_lights]]` light emits.
#[derive(Clone, Copy, Default, Deserialize, PartialEq)]
#[serde(rename_all = "lowercase")]
enum Face {
    /// Away from the surface it floats over.
    #[default]
    Away,
    /// Toward the surface (a small lamp lighting a pool on the wall; seen
    /// from the room it is its dark back).
    Surface,
    /// Every way: uniform on the sphere, per light.
    Random,
}

fn one_u32() -> u32 {
    1
}

/// Most lights `[[scatter_lights]]` places.
const MAX_SCATTER: u32 = 1 << 20;

/// The `[[scatter_lights]]` triangles over `scene`'s non-emissive surfaces
/// (see [`ScatterDef`]): a point uniform by area on them
/// ([`Surfaces::sample`]), the light's normal the surface's (front side;
/// the Cornell box's walls face the room, its blocks face out), reversed
/// for `face = "surface"` or uniform on the sphere for `face = "random"`;
/// each light is rotated about its normal at random. Random numbers come
/// from the light's [`Stream`].
fn scatter_lights(scene: &Scene, d: &ScatterDef) -> Result<Vec<[Vec3; 3]>, String> {
    let surfaces = Surfaces::new(scene)?;
    let mut out = Vec::with_capacity(d.count as usize);
    for k in 0..d.count {
        let mut s = Stream::new(d.seed, k);
        let (p, n) = surfaces.sample(&mut s);
        let spin = s.uniform();
        // The light's plane: the surface's, or any (`random`); its offset
        // is always to the surface's front.
        let axis = if d.face == Face::Random { s.direction() } else { n };
        // An orthonormal frame (t, s, axis) rotated by a random angle.
        let (t0, s0) = axis.any_orthonormal_pair();
        let phi = std::f32::consts::TAU * spin;
        let (t, s) = (t0 * phi.cos() + s0 * phi.sin(), s0 * phi.cos() - t0 * phi.sin());
        let r = d.size / 3f32.sqrt();
        let o = p + n * d.offset;
        let corner = |k: f32| {
            let a = std::f32::consts::TAU * k / 3.0;
            o + (t * a.cos() + s * a.sin()) * r
        };
        // Counter-clockwise about the axis, so the triangle's normal is the
        // axis (or clockwise: −n, facing the surface).
        out.push(if d.face == Face::Surface {
            [corner(0.0), corner(2.0), corner(1.0)]
        } else {
            [corner(0.0), corner(1.0), corner(2.0)]
        });
    }
    Ok(out)
}

/// `[[light]]` and `[primary]`: one flat table per light with a `type` key,
/// so that a bad value's error carries its own key and line (serde's tagged
/// enums lose the position). Which keys a type needs is checked below.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LightDef {
    #[serde(rename = "type")]
    kind: String,
    position: Option<[f32; 3]>,
    direction: Option<[f32; 3]>,
    intensity: Option<[f32; 3]>,
    irradiance: Option<[f32; 3]>,
    inner: Option<f32>,
    outer: Option<f32>,
    file: Option<PathBuf>,
    nadir: Option<[f32; 3]>,
    reference: Option<[f32; 3]>,
    tint: Option<[f32; 3]>,
}

impl LightDef {
    /// The value of a key the light's type requires.
    fn need<T: Clone>(&self, what: &str, key: &str, v: &Option<T>) -> Result<T, String> {
        v.clone().ok_or_else(|| format!("{what}: type \"{}\" needs `{key}`", self.kind))
    }
    /// Keys given that the type does not use.
    fn unused(&self, what: &str, allowed: &[&str]) -> Result<(), String> {
        let given = [
            ("position", self.position.is_some()),
            ("direction", self.direction.is_some()),
            ("intensity", self.intensity.is_some()),
            ("irradiance", self.irradiance.is_some()),
            ("inner", self.inner.is_some()),
            ("outer", self.outer.is_some()),
            ("file", self.file.is_some()),
            ("nadir", self.nadir.is_some()),
            ("reference", self.reference.is_some()),
            ("tint", self.tint.is_some()),
        ];
        match given.iter().find(|(k, g)| *g && !allowed.contains(k)) {
            Some((k, _)) => Err(format!("{what}: `{k}` does not apply to type \"{}\"", self.kind)),
            None => Ok(()),
        }
    }
}

/// `[render]` settings of a scene file; each may be overridden on the
/// command line.
#[derive(Deserialize, Default, Clone, Debug, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct RenderSettings {
    /// Image width.
    #[serde(default, deserialize_with = "image_side")]
    pub width: Option<u32>,
    /// Image height.
    #[serde(default, deserialize_with = "image_side")]
    pub height: Option<u32>,
    /// VPL count.
    #[serde(default, deserialize_with = "vpl_count")]
    pub vpls: Option<u64>,
    /// `slc`, `clamp`, `none` or `reference` (the VPL frame), or a
    /// path-tracing method ([`crate::pt::PtMethod`]).
    #[serde(default, deserialize_with = "method")]
    pub method: Option<String>,
    /// The VPL frame's SLC error bound ε (`--app vpl`).
    #[serde(default, deserialize_with = "vpl_error_bound")]
    pub error_bound: Option<f32>,
    /// The path tracer's ε (`--app pt`): a number, `"auto"` or `"auto:C"`
    /// ([`BoundArg`]). Separate from `error_bound`: a scene's automatic
    /// path-tracing ε is tens of times the VPL frame's (0.28 against 0.008
    /// in points-volume-49152, where 0.008 gives ~35× the candidates per
    /// point and 1.8× the time per sample), so neither application reads
    /// the other's.
    #[serde(default, deserialize_with = "bound_arg")]
    pub pt_error_bound: Option<BoundArg>,
    /// Clamp range R.
    #[serde(default, deserialize_with = "clamp_range")]
    pub range: Option<f32>,
    /// Seed.
    pub seed: Option<u32>,
    /// Exposure.
    #[serde(default, deserialize_with = "exposure")]
    pub exposure: Option<f32>,
}

// `[render]`'s values are checked where they are read, by the checks the
// renderers run on the same values from flags, so that a bad one is
// reported with its key and line.

/// A `T` from the file, passed through `check`.
fn checked<'de, D: serde::Deserializer<'de>, T: Deserialize<'de>, U>(
    d: D,
    check: impl FnOnce(T) -> Result<U, String>,
) -> Result<Option<U>, D::Error> {
    check(T::deserialize(d)?).map(Some).map_err(serde::de::Error::custom)
}

/// An `f32` the file writes as any number: one past `f32`'s range is
/// reported as written, not as the `inf` it would round to.
fn as_f32(v: f64) -> Result<f32, String> {
    if (v as f32).is_finite() || !v.is_finite() {
        Ok(v as f32)
    } else {
        Err(format!("{v:?} is beyond f32's range"))
    }
}

fn image_side<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<u32>, D::Error> {
    checked(d, |n: u32| {
        crate::check_size(n, n).map(|_| n).map_err(|_| {
            format!("an image side must be within 1..={}, got {n}", crate::MAX_IMAGE_SIDE)
        })
    })
}

fn vpl_count<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<u64>, D::Error> {
    checked(d, |n: u64| crate::vpl::rsm_side(n).map(|_| n).map_err(|e| e.to_string()))
}

fn method<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<String>, D::Error> {
    checked(d, |m: String| {
        let pt = crate::pt::PtMethod::ALL.iter().any(|p| p.name() == m);
        if pt || crate::culling::Culling::named(&m, 1.0, 1.0, 1.0).is_ok() {
            return Ok(m);
        }
        let names: Vec<&str> = crate::pt::PtMethod::ALL.iter().map(|p| p.name()).collect();
        Err(format!(
            "method '{m}' is neither the VPL frame's (slc, clamp, none, reference) nor a path tracer's ({})",
            names.join(", ")
        ))
    })
}

/// An error bound ε as the file writes it, checked as `RangeParams` checks it.
fn error_bound_value(v: f64) -> Result<f32, String> {
    let e = as_f32(v)?;
    slc_core::range::RangeParams::new(e, 1.0).map(|_| e).map_err(|e| e.to_string())
}

fn vpl_error_bound<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<f32>, D::Error> {
    checked(d, error_bound_value)
}

fn clamp_range<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<f32>, D::Error> {
    checked(d, |v: f64| {
        let r = as_f32(v)?;
        crate::culling::Culling::clamped(r).map(|_| r).map_err(|e| e.to_string())
    })
}

fn exposure<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<f32>, D::Error> {
    checked(d, |v: f64| {
        let e = as_f32(v)?;
        crate::check_exposure(e).map(|_| e).map_err(|e| e.to_string())
    })
}

/// `[render] pt_error_bound`: a TOML number or a string [`BoundArg`] parses.
fn bound_arg<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<BoundArg>, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Raw {
        Number(f64),
        Text(String),
    }
    let bound = match Raw::deserialize(d)? {
        Raw::Number(v) => error_bound_value(v).map(BoundArg::Value),
        Raw::Text(t) => t.parse(),
    };
    bound.map(Some).map_err(serde::de::Error::custom)
}

/// A loaded scene file.
pub struct SceneFile {
    /// Geometry (emissive meshes included), camera and primary light.
    pub scene: Scene,
    /// Point, spot and IES lights (for the path tracer; the VPL application
    /// lights the scene with its primary light only).
    pub lights: Vec<Light>,
    /// Render settings.
    pub render: RenderSettings,
}

/// A light's error as the file states it: a spot's cone angles in the
/// degrees it was given (`inner`, `outer`), not the radians
/// [`SpotLight::new`] reports.
fn in_degrees(e: LightError, inner: f32, outer: f32) -> String {
    match e {
        LightError::ConeAngles { .. } => format!(
            "spot cone angles must satisfy 0 <= inner <= outer <= 180 degrees, got inner {inner}, outer {outer}"
        ),
        e => e.to_string(),
    }
}

fn v3(a: [f32; 3]) -> Vec3 {
    Vec3::from(a)
}

impl SceneFile {
    /// Reads and validates a scene file.
    pub fn load(path: &Path) -> Result<SceneFile, SceneError> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| SceneError::Io(path.display().to_string(), e.to_string()))?;
        Self::parse(&text, path.parent().unwrap_or(Path::new(".")), &path.display().to_string())
    }

    /// Parses scene-file text; relative paths resolve against `dir`.
    pub fn parse(text: &str, dir: &Path, name: &str) -> Result<SceneFile, SceneError> {
        let f: File =
            toml::from_str(text).map_err(|e| SceneError::File(name.to_string(), e.to_string()))?;
        let bad = |what: String| SceneError::File(name.to_string(), what);
        let mut scene = Scene {
            name: Path::new(name)
                .file_stem()
                .map_or("scene".into(), |s| s.to_string_lossy().into_owned()),
            triangles: Vec::new(),
            normals: Vec::new(),
            material_of: Vec::new(),
            materials: Vec::new(),
            camera: Scene::cornell_box().camera,
            primary: Scene::cornell_box().primary,
            unsupported: Vec::new(),
        };
        let append = |scene: &mut Scene, other: Scene, scale: f32, translate: [f32; 3]| {
            scene.append(other, scale, v3(translate))
        };
        // glTF punctual lights, with the index of the geometry that placed them.
        let mut gltf_lights: Vec<(Light, usize)> = Vec::new();
        if f.geometry.is_empty() && f.emissive_mesh.is_empty() {
            return Err(bad(
                "the scene needs at least one [[geometry]] or [[emissive_mesh]]".into()
            ));
        }
        for (i, g) in f.geometry.iter().enumerate() {
            if !(g.scale.is_finite() && g.scale > 0.0) {
                return Err(bad(format!("geometry {i}: scale {} must be finite and > 0", g.scale)));
            }
            if !(g.emission_scale.is_finite() && g.emission_scale >= 0.0) {
                return Err(bad(format!(
                    "geometry {i}: emission_scale {} must be finite and >= 0",
                    g.emission_scale
                )));
            }
            let mut part = match (&g.builtin, &g.obj, &g.gltf) {
                (Some(b), None, None) if b == "cornell" => Scene::cornell_box(),
                (Some(b), None, None) if b == "cornell-glossy" => Scene::cornell_box_glossy(),
                (Some(b), None, None) if b == "sphere" => crate::shapes::sphere(4),
                (Some(b), None, None) => {
                    return Err(bad(format!(
                        "geometry {i}: unknown builtin '{b}' (known: cornell, cornell-glossy, sphere)"
                    )));
                }
                (None, Some(p), None) => {
                    let p = dir.join(p);
                    Scene::load_obj(&p).map_err(|e| e.in_file(&p))?
                }
                (None, None, Some(p)) => {
                    let p = dir.join(p);
                    let g = GltfScene::load(&p).map_err(|e| e.in_file(&p))?;
                    gltf_lights.extend(g.lights.iter().map(|l| (l.clone(), i)));
                    g.scene
                }
                _ => {
                    return Err(bad(format!(
                        "geometry {i}: give exactly one of `builtin`, `obj` or `gltf`"
                    )));
                }
            };
            if let Some(m) = &g.material {
                let m = m.material().map_err(|e| bad(format!("geometry {i}: {e}")))?;
                part.materials = vec![m];
                part.material_of.iter_mut().for_each(|k| *k = 0);
            }
            for m in &mut part.materials {
                m.emission *= g.emission_scale;
            }
            append(&mut scene, part, g.scale, g.translate);
        }
        for (i, e) in f.emissive_mesh.iter().enumerate() {
            if e.subdivide > 4 {
                return Err(bad(format!(
                    "emissive_mesh {i}: subdivide {} is above 4 (256 triangles per input triangle)",
                    e.subdivide
                )));
            }
            let emission = v3(e.emission);
            if !(emission.is_finite() && emission.min_element() >= 0.0) {
                return Err(bad(format!("emissive_mesh {i}: emission must be finite and >= 0")));
            }
            let p = dir.join(&e.obj);
            let mut mesh = Scene::load_obj(&p).map_err(|e| e.in_file(&p))?;
            if mesh.has_vertex_normals() {
                mesh.normals = subdivide_normals(&mesh.normals, e.subdivide);
            }
            mesh.triangles = subdivide(&mesh.triangles, e.subdivide);
            mesh.material_of = vec![0; mesh.triangles.len()];
            mesh.materials = vec![Material::lambertian(Vec3::splat(0.5), emission)];
            append(&mut scene, mesh, e.scale, e.translate);
        }
        for (i, d) in f.scatter_lights.iter().enumerate() {
            let emission = v3(d.emission);
            if !(1..=MAX_SCATTER).contains(&d.count) {
                return Err(bad(format!(
                    "scatter_lights {i}: count {} must be in 1..={MAX_SCATTER}",
                    d.count
                )));
            }
            if !(d.size.is_finite() && d.size > 0.0 && d.offset.is_finite() && d.offset >= 0.0) {
                return Err(bad(format!(
                    "scatter_lights {i}: size {} must be finite and > 0, offset {} finite and >= 0",
                    d.size, d.offset
                )));
            }
            if !(emission.is_finite() && emission.min_element() >= 0.0) {
                return Err(bad(format!("scatter_lights {i}: emission must be finite and >= 0")));
            }
            let triangles =
                scatter_lights(&scene, d).map_err(|e| bad(format!("scatter_lights {i}: {e}")))?;
            let lights = Scene {
                name: String::new(),
                material_of: vec![0; triangles.len()],
                normals: Vec::new(),
                triangles,
                materials: vec![Material::lambertian(Vec3::splat(0.5), emission)],
                camera: scene.camera,
                primary: scene.primary,
                unsupported: Vec::new(),
            };
            append(&mut scene, lights, 1.0, [0.0; 3]);
        }
        if let Some(c) = f.camera {
            scene.camera = Camera {
                position: v3(c.position),
                target: v3(c.look_at),
                up: v3(c.up),
                vfov_deg: c.fov,
            };
        } else if !f
            .geometry
            .iter()
            .any(|g| matches!(g.builtin.as_deref(), Some("cornell" | "cornell-glossy")))
        {
            // No camera: frame the bounds (built-in geometry keeps its own,
            // the published Cornell camera set above).
            let primary = scene.primary;
            scene.frame_default_view();
            scene.primary = primary;
        }
        match &f.primary {
            Some(l) if l.kind == "spot" => {
                let w = "[primary]";
                l.unused(w, &["position", "direction", "intensity", "inner", "outer"])
                    .map_err(bad)?;
                let (position, direction, intensity) = (
                    v3(l.need(w, "position", &l.position).map_err(bad)?),
                    v3(l.need(w, "direction", &l.direction).map_err(bad)?),
                    v3(l.need(w, "intensity", &l.intensity).map_err(bad)?),
                );
                let (inner, outer) =
                    (l.inner.unwrap_or(0.0), l.need(w, "outer", &l.outer).map_err(bad)?);
                // The light's own checks, reported in the file's degrees.
                SpotLight::new(
                    position,
                    direction,
                    intensity,
                    inner.to_radians(),
                    outer.to_radians(),
                )
                .map_err(|e| bad(format!("{w}: {}", in_degrees(e, inner, outer))))?;
                scene.primary = PrimaryLight::Spot {
                    position,
                    direction: direction.normalize_or_zero(),
                    intensity,
                    inner: inner.to_radians(),
                    outer: outer.to_radians(),
                }
            }
            Some(l) if l.kind == "directional" => {
                let w = "[primary]";
                l.unused(w, &["direction", "irradiance"]).map_err(bad)?;
                scene.primary = PrimaryLight::Directional {
                    direction: v3(l.need(w, "direction", &l.direction).map_err(bad)?),
                    irradiance: v3(l.need(w, "irradiance", &l.irradiance).map_err(bad)?),
                }
            }
            Some(l) => {
                return Err(bad(format!(
                    "[primary]: type \"{}\" is not \"spot\" or \"directional\"",
                    l.kind
                )));
            }
            None if f
                .geometry
                .iter()
                .any(|g| matches!(g.builtin.as_deref(), Some("cornell" | "cornell-glossy"))) => {}
            None => {
                let camera = scene.camera;
                scene.frame_default_view();
                scene.camera = camera;
            }
        }
        scene.validate().map_err(|e| bad(e.to_string()))?;
        // glTF lights move and scale with their geometry.
        let mut lights = Vec::new();
        for (l, i) in gltf_lights {
            lights.push(
                l.placed(f.geometry[i].scale, v3(f.geometry[i].translate))
                    .map_err(|e| bad(format!("geometry {i}: light {e}")))?,
            );
        }
        for (i, l) in f.light.iter().enumerate() {
            let w = format!("[[light]] {i}");
            let err = |e: slc_core::LightError| bad(format!("{w}: {e}"));
            let need3 = |key: &str, v: &Option<[f32; 3]>| l.need(&w, key, v).map(v3).map_err(bad);
            lights.push(match l.kind.as_str() {
                "point" => {
                    l.unused(&w, &["position", "intensity"]).map_err(bad)?;
                    Light::Point(
                        PointLight::new(
                            need3("position", &l.position)?,
                            need3("intensity", &l.intensity)?,
                        )
                        .map_err(err)?,
                    )
                }
                "spot" => {
                    l.unused(&w, &["position", "direction", "intensity", "inner", "outer"])
                        .map_err(bad)?;
                    let (inner, outer) =
                        (l.inner.unwrap_or(0.0), l.need(&w, "outer", &l.outer).map_err(bad)?);
                    Light::Spot(
                        SpotLight::new(
                            need3("position", &l.position)?,
                            need3("direction", &l.direction)?,
                            need3("intensity", &l.intensity)?,
                            inner.to_radians(),
                            outer.to_radians(),
                        )
                        .map_err(|e| bad(format!("{w}: {}", in_degrees(e, inner, outer))))?,
                    )
                }
                "ies" => {
                    l.unused(&w, &["position", "file", "nadir", "reference", "tint"])
                        .map_err(bad)?;
                    let p = dir.join(l.need(&w, "file", &l.file).map_err(bad)?);
                    let bytes = std::fs::read(&p)
                        .map_err(|e| SceneError::Io(p.display().to_string(), e.to_string()))?;
                    let profile = IesProfile::parse_bytes(&bytes)
                        .map_err(|e| bad(format!("{w}: {}: {e}", p.display())))?;
                    Light::Ies(
                        IesLight::new(
                            need3("position", &l.position)?,
                            v3(l.nadir.unwrap_or([0.0, -1.0, 0.0])),
                            v3(l.reference.unwrap_or([1.0, 0.0, 0.0])),
                            v3(l.tint.unwrap_or([1.0, 1.0, 1.0])),
                            Arc::new(profile),
                        )
                        .map_err(err)?,
                    )
                }
                other => {
                    return Err(bad(format!(
                        "{w}: type \"{other}\" is not \"point\", \"spot\" or \"ies\""
                    )));
                }
            });
        }
        for (i, c) in f.light_cloud.iter().enumerate() {
            lights.extend(c.lights(&scene, dir).map_err(|e| bad(format!("light_cloud {i}: {e}")))?);
        }
        Ok(SceneFile { scene, lights, render: f.render })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_keys_name_the_key_and_line() {
        let text = "[[geometry]]\nbuiltin = \"cornell\"\n\n[render]\nwidht = 3\n";
        let e = SceneFile::parse(text, Path::new("."), "t.toml").err().unwrap().to_string();
        assert!(e.contains("widht") && e.contains("line 5"), "{e}");
        let text =
            "[[geometry]]\nbuiltin = \"cornell\"\n[primary]\ntype = \"spot\"\nposition = [0, 1]\n";
        let e = SceneFile::parse(text, Path::new("."), "t.toml").err().unwrap().to_string();
        assert!(e.contains("line 5") && e.contains("position"), "{e}");
        let text = "[[geometry]]\nbuiltin = \"cornell\"\n[primary]\ntype = \"spot\"\nposition = [0, 1, 0]\n";
        let e = SceneFile::parse(text, Path::new("."), "t.toml").err().unwrap().to_string();
        assert!(e.contains("needs `direction`"), "{e}");
        let text = "[[geometry]]\nbuiltin = \"cornell\"\n[[light]]\ntype = \"point\"\nposition = [0, 1, 0]\nintensity = [1, 1, 1]\nouter = 3.0\n";
        let e = SceneFile::parse(text, Path::new("."), "t.toml").err().unwrap().to_string();
        assert!(e.contains("`outer` does not apply"), "{e}");
    }

    #[test]
    fn bad_values_are_errors() {
        for text in [
            "[[geometry]]\nbuiltin = \"moon\"\n",
            "[[geometry]]\nbuiltin = \"cornell\"\nscale = -1.0\n",
            "[[geometry]]\nbuiltin = \"cornell\"\nemission_scale = -1.0\n",
            "",
            "[[geometry]]\nbuiltin = \"cornell\"\n[[light]]\ntype = \"point\"\nposition = [0, 0, 0]\nintensity = [-1, 0, 0]\n",
            "[[geometry]]\nbuiltin = \"cornell\"\n[[light]]\ntype = \"laser\"\nposition = [0, 0, 0]\n",
            "[[geometry]]\nbuiltin = \"cornell\"\n[camera]\nposition = [0, 0, 0]\nlook_at = [0, 0, 0]\n",
        ] {
            assert!(
                SceneFile::parse(text, Path::new("."), "t.toml").is_err(),
                "{text:?} was accepted"
            );
        }
    }

    /// Errors say what is wrong in the file's terms: a spot's cone in the
    /// degrees it was written in, the primary light's actual fault, a mesh
    /// with no area (which a default camera cannot frame) by its file.
    #[test]
    fn errors_speak_the_files_terms() {
        let cornell = "[[geometry]]\nbuiltin = \"cornell\"\n";
        let spot = "position = [0, 1, 0]\ndirection = [0, -1, 0]\nintensity = [1, 1, 1]\n";
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("flat.obj"), "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n")
            .unwrap();
        for (text, says) in [
            (
                format!("{cornell}[[light]]\ntype = \"spot\"\n{spot}inner = 50\nouter = 40\n"),
                "[[light]] 0: spot cone angles must satisfy 0 <= inner <= outer <= 180 degrees, \
                 got inner 50, outer 40",
            ),
            (
                format!("{cornell}[primary]\ntype = \"spot\"\n{spot}outer = 190\n"),
                "[primary]: spot cone angles must satisfy 0 <= inner <= outer <= 180 degrees, \
                 got inner 0, outer 190",
            ),
            (
                format!(
                    "{cornell}[primary]\ntype = \"spot\"\n{}outer = 30\n",
                    spot.replace("[0, -1, 0]", "[0, 0, 0]")
                ),
                "[primary]: light direction has zero length",
            ),
            (
                "[[geometry]]\nobj = \"flat.obj\"\n".into(),
                "flat.obj: invalid scene: all 1 triangles have zero area",
            ),
        ] {
            let e =
                SceneFile::parse(&text, dir.path(), "t.toml").err().expect("accepted").to_string();
            assert!(e.contains(says), "{text:?}: {e}");
        }
    }

    /// `[render]` holds one ε per application: `error_bound` the VPL
    /// frame's, `pt_error_bound` the path tracer's (a number, `auto` or
    /// `auto:C`), and neither sets the other.
    #[test]
    fn each_application_has_its_own_error_bound() {
        let render = |line: &str| {
            let text = format!("[[geometry]]\nbuiltin = \"cornell\"\n[render]\n{line}\n");
            SceneFile::parse(&text, Path::new("."), "t.toml").map(|f| f.render)
        };
        let vpl = render("error_bound = 0.008").unwrap();
        assert_eq!((vpl.error_bound, vpl.pt_error_bound), (Some(0.008), None));
        for (line, bound) in [
            ("pt_error_bound = 0.5", BoundArg::Value(0.5)),
            ("pt_error_bound = 2", BoundArg::Value(2.0)),
            ("pt_error_bound = \"auto\"", BoundArg::Auto(crate::error_bound::TARGET_CANDIDATES)),
            ("pt_error_bound = \"auto:3\"", BoundArg::Auto(3.0)),
        ] {
            let r = render(line).unwrap();
            assert_eq!((r.error_bound, r.pt_error_bound), (None, Some(bound)), "{line}");
        }
        for line in [
            "pt_error_bound = \"automatic\"",
            "pt_error_bound = \"auto:x\"",
            "pt_error_bound = [1]",
            "pt_error_bound = -1",
            "pt_error_bound = 1e40",
            "pt_error_bound = nan",
        ] {
            let e = render(line).expect_err("accepted").to_string();
            assert!(e.contains("pt_error_bound") && e.contains("line 4"), "{line}: {e}");
        }
    }

    /// Every `[render]` value is checked where it is read, by the same
    /// checks as the flags', so its error names the key and the line.
    #[test]
    fn render_values_are_checked_with_their_line() {
        let render = |line: &str| {
            let text = format!("[[geometry]]\nbuiltin = \"cornell\"\n[render]\n{line}\n");
            SceneFile::parse(&text, Path::new("."), "t.toml").map(|f| f.render)
        };
        for (line, says) in [
            ("width = 0", "1..=16384, got 0"),
            ("height = 20000", "got 20000"),
            ("vpls = 1000", "1000 VPLs"),
            ("method = \"fast\"", "method 'fast' is neither"),
            ("error_bound = 0.0", "error bound"),
            ("error_bound = 1e40", "1e40 is beyond f32's range"),
            ("range = 0.0", "clamp range 0"),
            ("exposure = -1.0", "exposure -1"),
        ] {
            let e = render(line).expect_err("accepted").to_string();
            let key = line.split(' ').next().unwrap();
            assert!(e.contains(says) && e.contains("line 4") && e.contains(key), "{line}: {e}");
        }
        let ok = render("width = 64\nvpls = 4096\nmethod = \"slc-weighted\"\nerror_bound = 0.008\nrange = 0.1\nexposure = 2").unwrap();
        assert_eq!(
            (ok.width, ok.vpls, ok.method.as_deref(), ok.error_bound, ok.range, ok.exposure),
            (Some(64), Some(4096), Some("slc-weighted"), Some(0.008), Some(0.1), Some(2.0))
        );
        assert_eq!(render("method = \"clamp\"").unwrap().method.as_deref(), Some("clamp"));
    }

    /// The module docs' example, every key it shows, loads (its paths
    /// are relative to a file in `scenes/`, beside `../shared`).
    #[test]
    fn the_documented_example_loads() {
        let doc: String = include_str!("scene_file.rs")
            .lines()
            .filter_map(|l| l.strip_prefix("//!"))
            .map(|l| l.strip_prefix(' ').unwrap_or(l))
            .skip_while(|l| !l.starts_with("```toml"))
            .skip(1)
            .take_while(|l| !l.starts_with("```"))
            .map(|l| format!("{l}\n"))
            .collect();
        slc_test_data::shared_data("ies");
        let dir = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes");
        let f = SceneFile::parse(&doc, &dir, "doc.toml").expect("the documented example");
        assert!(doc.contains("pt_error_bound") && f.render.pt_error_bound.is_some(), "{doc}");
        assert!(!f.lights.is_empty() && f.render.exposure == Some(1.0));
    }

    #[test]
    fn subdivision_quadruples_and_keeps_area() {
        let t = [[Vec3::ZERO, Vec3::X, Vec3::Y]];
        let s = subdivide(&t, 2);
        assert_eq!(s.len(), 16);
        let area: f32 = s.iter().map(|[a, b, c]| 0.5 * (*b - *a).cross(*c - *a).length()).sum();
        assert!((area - 0.5).abs() < 1e-6);
    }

    /// `[[scatter_lights]]` places `count` lights of the given size, each
    /// `offset` in front of a surface triangle and facing the way it does
    /// (in the Cornell box: into the room, or out of a block); the same
    /// seed places them the same way; bad values are errors.
    #[test]
    fn scattered_lights_face_the_room() {
        let text = "[[geometry]]\nbuiltin = \"cornell\"\nemission_scale = 0.0\n[[scatter_lights]]\ncount = 500\nsize = 0.01\noffset = 0.002\nemission = [1, 1, 1]\n";
        let f = SceneFile::parse(text, Path::new("."), "t.toml").unwrap();
        let base = Scene::cornell_box();
        assert_eq!(f.scene.triangles.len(), base.triangles.len() + 500);
        for t in &f.scene.triangles[base.triangles.len()..] {
            let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize();
            let foot = (t[0] + t[1] + t[2]) / 3.0 - n * 0.002;
            // A surface whose plane holds the foot point and whose normal is the light's.
            let on = base.triangles.iter().any(|s| {
                let sn = (s[1] - s[0]).cross(s[2] - s[0]).normalize();
                sn.dot(n) > 0.9999 && sn.dot(foot - s[0]).abs() < 1e-4
            });
            assert!(on, "light at {foot} is not in front of a surface, facing its way");
            assert!(((t[1] - t[0]).length() - 0.01).abs() < 1e-5);
        }
        assert_eq!(
            SceneFile::parse(text, Path::new("."), "t.toml").unwrap().scene.triangles,
            f.scene.triangles
        );
        let facing =
            SceneFile::parse(&format!("{text}face = \"surface\"\n"), Path::new("."), "t.toml")
                .unwrap();
        for (a, b) in
            facing.scene.triangles.iter().zip(&f.scene.triangles).skip(base.triangles.len())
        {
            let n = |t: &[Vec3; 3]| (t[1] - t[0]).cross(t[2] - t[0]).normalize();
            assert!(n(a).dot(n(b)) < -0.9999, "face = \"surface\" flips the light");
        }
        assert!(
            SceneFile::parse(&format!("{text}face = \"up\"\n"), Path::new("."), "t.toml").is_err()
        );
        for bad in ["count = 0", "size = -1.0", "offset = -0.1", "emission = [1, -1, 1]"] {
            let key = bad.split(' ').next().unwrap();
            let t = text
                .lines()
                .map(|l| {
                    if l.starts_with(&format!("{key} ")) { bad.to_string() } else { l.to_string() }
                })
                .collect::<Vec<_>>()
                .join("\n");
            assert!(SceneFile::parse(&t, Path::new("."), "t.toml").is_err(), "{bad}");
        }
    }

    #[test]
    fn builtin_geometry_keeps_its_camera() {
        let f = SceneFile::parse("[[geometry]]\nbuiltin = \"cornell\"\n", Path::new("."), "t.toml")
            .unwrap();
        assert_eq!(f.scene.camera, Scene::cornell_box().camera);
    }

    #[test]
    fn builtin_with_primary_and_render() {
        let text = "[[geometry]]\nbuiltin = \"cornell\"\n[primary]\ntype = \"directional\"\ndirection = [0, -1, 0.2]\nirradiance = [1, 1, 1]\n[render]\nwidth = 64\nmethod = \"clamp\"\n";
        let f = SceneFile::parse(text, Path::new("."), "t.toml").unwrap();
        assert_eq!(f.render.width, Some(64));
        assert!(matches!(f.scene.primary, PrimaryLight::Directional { .. }));
        assert_eq!(f.scene.triangles.len(), 32);
    }
}
