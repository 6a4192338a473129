//! Scenes: triangles with diffuse albedo and emission, a pinhole camera and a
//! primary light. Loaded from OBJ+MTL (`Kd`, `Ke`) with `tobj`, or the
//! built-in Cornell box written from its published measurements.

use crate::SceneError;
use glam::Vec3;
use slc_core::light::SpotLight;
use std::path::Path;

/// A diffuse material.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Diffuse reflectance ρ per channel, in `[0, 1]`.
    pub albedo: Vec3,
    /// Emitted radiance (`Ke`), `≥ 0`.
    pub emission: Vec3,
}

/// A pinhole camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Eye position.
    pub position: Vec3,
    /// Point looked at.
    pub target: Vec3,
    /// Up hint.
    pub up: Vec3,
    /// Vertical field of view in degrees.
    pub vfov_deg: f32,
}

impl Camera {
    /// Orthonormal basis `(right, up, forward)`.
    pub fn basis(&self) -> (Vec3, Vec3, Vec3) {
        let f = (self.target - self.position).normalize();
        let r = f.cross(self.up).normalize();
        let u = r.cross(f);
        (r, u, f)
    }

    /// Unit direction through pixel centre `(x, y)` of a `w × h` image
    /// (y down).
    pub fn ray_dir(&self, x: f32, y: f32, w: u32, h: u32) -> Vec3 {
        let (f, r, u) = self.scaled_basis(w, h);
        slc_core::path::camera_dir(f, r, u, x + 0.5, y + 0.5, w as f32, h as f32)
    }

    /// `(forward, right · tan(fov/2) · aspect, up · tan(fov/2))` for a
    /// `w × h` image, the vectors [`slc_core::path::camera_dir`] takes.
    pub fn scaled_basis(&self, w: u32, h: u32) -> (Vec3, Vec3, Vec3) {
        let (r, u, f) = self.basis();
        let t = (self.vfov_deg.to_radians() * 0.5).tan();
        (f, r * (t * w as f32 / h as f32), u * t)
    }
}

/// The light that illuminates the scene directly and whose reflections
/// become the VPLs (through the reflective shadow map).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PrimaryLight {
    /// A spot light; its RSM is a perspective map over the outer cone.
    Spot {
        /// Position.
        position: Vec3,
        /// Unit axis.
        direction: Vec3,
        /// Peak RGB intensity (W/sr).
        intensity: Vec3,
        /// Full-intensity half-angle (radians).
        inner: f32,
        /// Cut-off half-angle (radians), below 85°.
        outer: f32,
    },
    /// A directional light; its RSM is an orthographic map over the scene.
    Directional {
        /// Unit direction the light travels in.
        direction: Vec3,
        /// RGB irradiance on a surface facing the light (W/m²).
        irradiance: Vec3,
    },
}

impl PrimaryLight {
    /// The slc-core spot light this primary light is (for spots).
    pub fn spot(&self) -> Option<SpotLight> {
        match *self {
            PrimaryLight::Spot { position, direction, intensity, inner, outer } => SpotLight::new(position, direction, intensity, inner, outer).ok(),
            PrimaryLight::Directional { .. } => None,
        }
    }
}

/// Triangles, materials, camera and primary light.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// Name for reports.
    pub name: String,
    /// Triangle vertices.
    pub triangles: Vec<[Vec3; 3]>,
    /// Material index per triangle.
    pub material_of: Vec<u32>,
    /// Materials.
    pub materials: Vec<Material>,
    /// Camera.
    pub camera: Camera,
    /// Primary light.
    pub primary: PrimaryLight,
}

/// `true` when an MTL colour line (`Ka`, `Kd`, `Ks`, `Ke`) has fewer than
/// three values: tobj 4.0.5 panics on those (`parse_float3` unwraps a
/// short array), so they are rejected as a parse error before tobj sees
/// them. Found by fuzz/scene_loaders.
fn short_colour_line(mtl: &[u8]) -> bool {
    String::from_utf8_lossy(mtl).lines().any(|l| {
        let mut w = l.split_whitespace();
        matches!(w.next(), Some("Ka" | "Kd" | "Ks" | "Ke")) && w.take(3).count() < 3
    })
}

impl Scene {
    /// Checks the invariants every renderer relies on: finite vertices,
    /// valid material indices, albedo in `[0, 1]`, non-negative finite
    /// emission, a usable camera and primary light.
    pub fn validate(&self) -> Result<(), SceneError> {
        if self.triangles.is_empty() {
            return Err(SceneError::Empty);
        }
        if self.material_of.len() != self.triangles.len() {
            return Err(SceneError::Invalid("one material index per triangle".into()));
        }
        for (i, t) in self.triangles.iter().enumerate() {
            if !t.iter().all(|v| v.is_finite()) {
                return Err(SceneError::NonFiniteVertex(i));
            }
            if self.material_of[i] as usize >= self.materials.len() {
                return Err(SceneError::Invalid(format!("triangle {i} names material {} of {}", self.material_of[i], self.materials.len())));
            }
        }
        for (i, m) in self.materials.iter().enumerate() {
            if !(m.albedo.is_finite() && m.albedo.min_element() >= 0.0 && m.albedo.max_element() <= 1.0) {
                return Err(SceneError::Invalid(format!("material {i}: albedo {:?} outside [0, 1]", m.albedo)));
            }
            if !(m.emission.is_finite() && m.emission.min_element() >= 0.0) {
                return Err(SceneError::Invalid(format!("material {i}: emission {:?} must be finite and >= 0", m.emission)));
            }
        }
        let c = &self.camera;
        let fwd = c.target - c.position;
        if !(c.position.is_finite() && c.target.is_finite() && fwd.length() > 0.0 && fwd.cross(c.up).length() > 0.0) {
            return Err(SceneError::Invalid("camera: position, target and up must be finite, distinct and not parallel".into()));
        }
        if !(c.vfov_deg > 0.0 && c.vfov_deg < 180.0) {
            return Err(SceneError::Invalid(format!("camera: vertical fov {} must be in (0, 180)", c.vfov_deg)));
        }
        match self.primary {
            PrimaryLight::Spot { outer, .. } => {
                self.primary.spot().ok_or_else(|| SceneError::Invalid("primary spot light is invalid".into()))?;
                if outer >= 85f32.to_radians() {
                    return Err(SceneError::Invalid("primary spot outer angle must be below 85 degrees".into()));
                }
            }
            PrimaryLight::Directional { direction, irradiance } => {
                if !(direction.is_finite() && direction.length() > 0.0 && irradiance.is_finite() && irradiance.min_element() >= 0.0) {
                    return Err(SceneError::Invalid("primary directional light is invalid".into()));
                }
            }
        }
        Ok(())
    }

    /// Axis-aligned bounds of all vertices.
    pub fn bounds(&self) -> (Vec3, Vec3) {
        self.triangles.iter().flatten().fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)))
    }

    /// Length of the bounds' diagonal.
    pub fn diagonal(&self) -> f32 {
        let (lo, hi) = self.bounds();
        (hi - lo).length()
    }

    /// The built-in Cornell box, from the measurements published by the
    /// Cornell Program of Computer Graphics ("Cornell Box Data"), converted
    /// from millimetres to metres, with the reflectances of McGuire's
    /// Computer Graphics Archive version. The primary light is a spot at the
    /// ceiling light's centre pointing down; its peak intensity is that of the
    /// measured light (radiance `(17, 12, 4)` times its 0.130 × 0.105 m area).
    pub fn cornell_box() -> Scene {
        let mm = |x: f32, y: f32, z: f32| Vec3::new(x, y, z) * 0.001;
        let white = Material { albedo: Vec3::new(0.725, 0.71, 0.68), emission: Vec3::ZERO };
        let red = Material { albedo: Vec3::new(0.63, 0.065, 0.05), emission: Vec3::ZERO };
        let green = Material { albedo: Vec3::new(0.14, 0.45, 0.091), emission: Vec3::ZERO };
        let light = Material { albedo: Vec3::splat(0.78), emission: Vec3::new(17.0, 12.0, 4.0) };
        let quads: [([[f32; 3]; 4], u32); 16] = [
            // Floor, ceiling, back wall (white), right wall (green), left wall (red).
            ([[552.8, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 559.2], [549.6, 0.0, 559.2]], 0),
            ([[556.0, 548.8, 0.0], [556.0, 548.8, 559.2], [0.0, 548.8, 559.2], [0.0, 548.8, 0.0]], 0),
            ([[549.6, 0.0, 559.2], [0.0, 0.0, 559.2], [0.0, 548.8, 559.2], [556.0, 548.8, 559.2]], 0),
            ([[0.0, 0.0, 559.2], [0.0, 0.0, 0.0], [0.0, 548.8, 0.0], [0.0, 548.8, 559.2]], 2),
            ([[552.8, 0.0, 0.0], [549.6, 0.0, 559.2], [556.0, 548.8, 559.2], [556.0, 548.8, 0.0]], 1),
            // Short block.
            ([[130.0, 165.0, 65.0], [82.0, 165.0, 225.0], [240.0, 165.0, 272.0], [290.0, 165.0, 114.0]], 0),
            ([[290.0, 0.0, 114.0], [290.0, 165.0, 114.0], [240.0, 165.0, 272.0], [240.0, 0.0, 272.0]], 0),
            ([[130.0, 0.0, 65.0], [130.0, 165.0, 65.0], [290.0, 165.0, 114.0], [290.0, 0.0, 114.0]], 0),
            ([[82.0, 0.0, 225.0], [82.0, 165.0, 225.0], [130.0, 165.0, 65.0], [130.0, 0.0, 65.0]], 0),
            ([[240.0, 0.0, 272.0], [240.0, 165.0, 272.0], [82.0, 165.0, 225.0], [82.0, 0.0, 225.0]], 0),
            // Tall block.
            ([[423.0, 330.0, 247.0], [265.0, 330.0, 296.0], [314.0, 330.0, 456.0], [472.0, 330.0, 406.0]], 0),
            ([[423.0, 0.0, 247.0], [423.0, 330.0, 247.0], [472.0, 330.0, 406.0], [472.0, 0.0, 406.0]], 0),
            ([[472.0, 0.0, 406.0], [472.0, 330.0, 406.0], [314.0, 330.0, 456.0], [314.0, 0.0, 456.0]], 0),
            ([[314.0, 0.0, 456.0], [314.0, 330.0, 456.0], [265.0, 330.0, 296.0], [265.0, 0.0, 296.0]], 0),
            ([[265.0, 0.0, 296.0], [265.0, 330.0, 296.0], [423.0, 330.0, 247.0], [423.0, 0.0, 247.0]], 0),
            // Light, 0.1 mm below the ceiling, facing down.
            ([[343.0, 548.7, 227.0], [343.0, 548.7, 332.0], [213.0, 548.7, 332.0], [213.0, 548.7, 227.0]], 3),
        ];
        let mut triangles = Vec::new();
        let mut material_of = Vec::new();
        for (q, m) in &quads {
            let v = q.map(|p| mm(p[0], p[1], p[2]));
            triangles.push([v[0], v[1], v[2]]);
            triangles.push([v[0], v[2], v[3]]);
            material_of.extend([*m, *m]);
        }
        let light_area = 0.130 * 0.105;
        Scene {
            name: "cornell".into(),
            triangles,
            material_of,
            materials: vec![white, red, green, light],
            camera: Camera {
                position: mm(278.0, 273.0, -800.0),
                target: mm(278.0, 273.0, 0.0),
                up: Vec3::Y,
                // 35 mm focal length, 25 mm film: 2·atan(12.5/35).
                vfov_deg: 2.0 * (12.5f32 / 35.0).atan().to_degrees(),
            },
            primary: PrimaryLight::Spot {
                position: mm(278.0, 548.0, 279.5),
                direction: -Vec3::Y,
                intensity: Vec3::new(17.0, 12.0, 4.0) * light_area,
                inner: 0.0,
                outer: 80f32.to_radians() * 0.99,
            },
        }
    }

    /// The built-in Cornell box with its ceiling light split into `n × n`
    /// quads (`2n²` triangle lights, same total emission): a small many-light
    /// scene for tests of light selection.
    pub fn cornell_box_split_light(n: u32) -> Scene {
        let mut s = Scene::cornell_box();
        let light = s.material_of.iter().position(|&m| s.materials[m as usize].emission.max_element() > 0.0).expect("the box has a light");
        let [a, b, _] = s.triangles[light];
        let c = s.triangles[light + 1][2];
        // The light quad is a (corner), a→b (first edge), a→d (second edge).
        let m = s.material_of[light];
        s.triangles.drain(light..light + 2);
        s.material_of.drain(light..light + 2);
        let (e1, e2) = (b - a, c - a);
        let n = n.max(1);
        for i in 0..n {
            for j in 0..n {
                let p = |u: u32, v: u32| a + e1 * (u as f32 / n as f32) + e2 * (v as f32 / n as f32);
                let (p00, p10, p11, p01) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
                s.triangles.push([p00, p10, p11]);
                s.triangles.push([p00, p11, p01]);
                s.material_of.extend([m, m]);
            }
        }
        s
    }

    /// Loads an OBJ with its MTL (`Kd` albedo, `Ke` emission; faces are
    /// triangulated). When the `mtllib` path does not exist relative to the
    /// OBJ, a `.mtl` of the same file name beside the OBJ is used. The camera
    /// looks at the bounds' centre along −z from in front of the +z face;
    /// the primary light is a spot at the emitters' centroid along their mean
    /// normal (or, with no emitter, above the scene pointing down).
    pub fn load_obj(path: &Path) -> Result<Scene, SceneError> {
        let text = std::fs::read(path).map_err(|e| SceneError::Io(path.display().to_string(), e.to_string()))?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let name = path.display().to_string();
        Self::parse_obj(&text, &name, |p| {
            let direct = dir.join(p);
            let fallback = p.file_name().map(|f| dir.join(f));
            let chosen = if direct.exists() { direct } else { fallback.filter(|f| f.exists()).unwrap_or(direct) };
            std::fs::read(&chosen).ok()
        })
    }

    /// Parses OBJ text; `mtl(name)` returns the bytes of a material library
    /// the OBJ names (or `None` when it cannot be found). `name` labels
    /// errors and the scene.
    pub fn parse_obj(obj: &[u8], name: &str, mtl: impl Fn(&Path) -> Option<Vec<u8>>) -> Result<Scene, SceneError> {
        let path = Path::new(name);
        let opts = tobj::LoadOptions { triangulate: true, single_index: false, ignore_points: true, ignore_lines: true };
        let (models, mats) = tobj::load_obj_buf(&mut &obj[..], &opts, |p| match mtl(p) {
            Some(b) if short_colour_line(&b) => Err(tobj::LoadError::MaterialParseError),
            Some(b) => tobj::load_mtl_buf(&mut b.as_slice()),
            None => Err(tobj::LoadError::OpenFileFailed),
        })
        .map_err(|e| SceneError::Obj(path.display().to_string(), e.to_string()))?;
        let mats = mats.map_err(|e| SceneError::Obj(path.display().to_string(), format!("material library: {e}")))?;
        let mut materials: Vec<Material> = mats
            .iter()
            .map(|m| {
                let kd = m.diffuse.map(Vec3::from).unwrap_or(Vec3::splat(0.8));
                let ke = m.emissive.map(Vec3::from).unwrap_or(Vec3::ZERO);
                Material { albedo: kd, emission: ke }
            })
            .collect();
        let default_mat = materials.len() as u32;
        materials.push(Material { albedo: Vec3::splat(0.8), emission: Vec3::ZERO });
        let mut triangles = Vec::new();
        let mut material_of = Vec::new();
        for m in &models {
            let mesh = &m.mesh;
            let mat = mesh.material_id.map_or(default_mat, |i| i as u32);
            for f in mesh.indices.chunks_exact(3) {
                let v = |i: u32| -> Result<Vec3, SceneError> {
                    let i = i as usize * 3;
                    mesh.positions
                        .get(i..i + 3)
                        .map(|p| Vec3::new(p[0], p[1], p[2]))
                        .ok_or_else(|| SceneError::Obj(path.display().to_string(), format!("vertex index {} out of range", i / 3)))
                };
                triangles.push([v(f[0])?, v(f[1])?, v(f[2])?]);
                material_of.push(mat);
            }
        }
        let name = path.file_stem().map_or("obj".into(), |s| s.to_string_lossy().into_owned());
        let mut scene = Scene {
            name,
            triangles,
            material_of,
            materials,
            camera: Camera { position: Vec3::Z, target: Vec3::ZERO, up: Vec3::Y, vfov_deg: 40.0 },
            primary: PrimaryLight::Directional { direction: -Vec3::Y, irradiance: Vec3::ONE },
        };
        if scene.triangles.is_empty() {
            return Err(SceneError::Empty);
        }
        scene.frame_default_view();
        scene.validate()?;
        Ok(scene)
    }

    /// Sets the default camera and primary light for a loaded scene (see
    /// [`Scene::load_obj`]).
    pub fn frame_default_view(&mut self) {
        let (lo, hi) = self.bounds();
        let c = (lo + hi) * 0.5;
        let ext = hi - lo;
        let vfov: f32 = 39.3;
        let dist = 0.5 * ext.y.max(ext.x) / (vfov.to_radians() * 0.5).tan();
        self.camera = Camera { position: Vec3::new(c.x, c.y, hi.z + dist * 1.02), target: c, up: Vec3::Y, vfov_deg: vfov };
        // Emitters: area-weighted centroid, mean normal, I₀ = Σ L·A.
        let (mut area_sum, mut centroid, mut normal, mut power) = (0.0f32, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
        for (t, &m) in self.triangles.iter().zip(&self.material_of) {
            let e = self.materials[m as usize].emission;
            if e.max_element() > 0.0 {
                let n = (t[1] - t[0]).cross(t[2] - t[0]);
                let a = 0.5 * n.length();
                if a > 0.0 {
                    area_sum += a;
                    centroid += (t[0] + t[1] + t[2]) / 3.0 * a;
                    normal += n.normalize() * a;
                    power += e * a;
                }
            }
        }
        self.primary = if area_sum > 0.0 && normal.length() > 0.0 {
            let n = normal.normalize();
            PrimaryLight::Spot {
                position: centroid / area_sum + n * 1e-3 * ext.length(),
                direction: n,
                intensity: power,
                inner: 0.0,
                outer: 80f32.to_radians() * 0.99,
            }
        } else {
            PrimaryLight::Spot {
                position: Vec3::new(c.x, hi.y + 0.25 * ext.length(), c.z),
                direction: -Vec3::Y,
                intensity: Vec3::splat(ext.length().powi(2)),
                inner: 0.0,
                outer: 70f32.to_radians(),
            }
        };
    }
}
