//! OBJ + MTL loading through tobj: positions, per-corner normals (`vn`,
//! smooth shading), `Kd` albedo and `Ke` emission. MTL features the renderer
//! does not model (`Ks`, `Ns`, `d`, `map_*`, ...) are returned in
//! [`Scene::unsupported`] for the caller to report.

use crate::SceneError;
use crate::scene::{Camera, Material, PrimaryLight, Scene, Unsupported};
use glam::Vec3;
use std::path::Path;

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

/// The MTL features of `m` that would change its look but that slc ignores:
/// a non-zero specular colour (with its exponent), transparency (with its
/// index of refraction), texture maps, and keys tobj does not know. `Ka`,
/// `illum` and a zero `Ks` (how most exporters write "diffuse") are silent.
fn unsupported_features(m: &tobj::Material) -> Vec<String> {
    let mut out = Vec::new();
    let specular = m.specular.is_some_and(|ks| ks.iter().any(|&k| k > 0.0));
    if specular {
        out.push("Ks".to_string());
        if m.shininess.is_some() {
            out.push("Ns".to_string());
        }
    }
    if m.dissolve.is_some_and(|d| d < 1.0) {
        out.push("d".to_string());
        if m.optical_density.is_some() {
            out.push("Ni".to_string());
        }
    }
    for (key, tex) in [
        ("map_Ka", &m.ambient_texture),
        ("map_Kd", &m.diffuse_texture),
        ("map_Ks", &m.specular_texture),
        ("map_Bump", &m.normal_texture),
        ("map_Ns", &m.shininess_texture),
        ("map_d", &m.dissolve_texture),
    ] {
        if tex.is_some() {
            out.push(key.to_string());
        }
    }
    let mut unknown: Vec<&String> = m.unknown_param.keys().filter(|k| !matches!(k.as_str(), "Tf" | "Ke")).collect();
    unknown.sort();
    out.extend(unknown.into_iter().cloned());
    out
}

impl Scene {
    /// Loads an OBJ with its MTL (`Kd` albedo, `Ke` emission, `vn` vertex
    /// normals; faces are triangulated). When the `mtllib` path does not
    /// exist relative to the OBJ, a `.mtl` of the same file name beside the
    /// OBJ is used. The camera looks at the bounds' centre along −z from in
    /// front of the +z face; the primary light is a spot at the emitters'
    /// centroid along their mean normal (or, with no emitter, above the
    /// scene pointing down).
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
    ///
    /// Vertex normals: a face whose corners all name a `vn` gets those
    /// normals (normalised); a `vn` index out of range is an error; a
    /// zero-length or non-finite `vn`, or a face without normals in a mesh
    /// that has some, falls back to the face's geometric normal.
    pub fn parse_obj(obj: &[u8], name: &str, mtl: impl Fn(&Path) -> Option<Vec<u8>>) -> Result<Scene, SceneError> {
        let path = Path::new(name);
        let err = |what: String| SceneError::Obj(path.display().to_string(), what);
        let opts = tobj::LoadOptions { triangulate: true, single_index: false, ignore_points: true, ignore_lines: true };
        let (models, mats) = tobj::load_obj_buf(&mut &obj[..], &opts, |p| match mtl(p) {
            Some(b) if short_colour_line(&b) => Err(tobj::LoadError::MaterialParseError),
            Some(b) => tobj::load_mtl_buf(&mut b.as_slice()),
            None => Err(tobj::LoadError::OpenFileFailed),
        })
        .map_err(|e| err(e.to_string()))?;
        let mats = mats.map_err(|e| err(format!("material library: {e}")))?;
        let file = path.file_name().map_or_else(|| name.to_string(), |f| f.to_string_lossy().into_owned());
        let unsupported = mats
            .iter()
            .filter_map(|m| {
                let features = unsupported_features(m);
                (!features.is_empty()).then(|| Unsupported { source: file.clone(), material: m.name.clone(), features })
            })
            .collect();
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
        let mut normals = Vec::new();
        let mut material_of = Vec::new();
        let any_normals = models.iter().any(|m| !m.mesh.normal_indices.is_empty());
        for m in &models {
            let mesh = &m.mesh;
            let mat = mesh.material_id.map_or(default_mat, |i| i as u32);
            let has_normals = mesh.normal_indices.len() == mesh.indices.len();
            for (f, corners) in mesh.indices.chunks_exact(3).enumerate() {
                let v = |i: u32| -> Result<Vec3, SceneError> {
                    let i = i as usize * 3;
                    mesh.positions
                        .get(i..i + 3)
                        .map(|p| Vec3::new(p[0], p[1], p[2]))
                        .ok_or_else(|| err(format!("vertex index {} out of range", i / 3)))
                };
                let tri = [v(corners[0])?, v(corners[1])?, v(corners[2])?];
                if any_normals {
                    let geometric = slc_core::ray::triangle_normal(tri[0], tri[1], tri[2]);
                    let mut ns = [geometric; 3];
                    if has_normals {
                        for (k, n) in ns.iter_mut().enumerate() {
                            let i = mesh.normal_indices[3 * f + k] as usize * 3;
                            let raw = mesh
                                .normals
                                .get(i..i + 3)
                                .map(|p| Vec3::new(p[0], p[1], p[2]))
                                .ok_or_else(|| err(format!("normal index {} out of range", i / 3)))?;
                            let unit = raw.normalize_or_zero();
                            if unit != Vec3::ZERO {
                                *n = unit;
                            }
                        }
                    }
                    // A degenerate face with no usable normal: any unit vector
                    // keeps the scene valid (it is never hit).
                    normals.push(ns.map(|n| if n == Vec3::ZERO { Vec3::Y } else { n }));
                }
                triangles.push(tri);
                material_of.push(mat);
            }
        }
        let name = path.file_stem().map_or("obj".into(), |s| s.to_string_lossy().into_owned());
        let mut scene = Scene {
            name,
            triangles,
            normals,
            material_of,
            materials,
            camera: Camera { position: Vec3::Z, target: Vec3::ZERO, up: Vec3::Y, vfov_deg: 40.0 },
            primary: PrimaryLight::Directional { direction: -Vec3::Y, irradiance: Vec3::ONE },
            unsupported,
        };
        if scene.triangles.is_empty() {
            return Err(SceneError::Empty);
        }
        scene.frame_default_view();
        scene.validate()?;
        Ok(scene)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const QUAD: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

    fn parse(obj: &str, mtl: Option<&str>) -> Result<Scene, SceneError> {
        let mtl = mtl.map(|m| m.as_bytes().to_vec());
        Scene::parse_obj(obj.as_bytes(), "t.obj", move |_| mtl.clone())
    }

    #[test]
    fn vertex_normals_are_read_and_normalised() {
        let s = parse(&format!("{QUAD}vn 0 0 2\nvn 0.6 0 0.8\nf 1//1 2//2 3//1\nf 1//1 3//1 4//2\n"), None).unwrap();
        assert_eq!(s.normals.len(), 2);
        assert_eq!(s.normals[0][0], Vec3::Z);
        assert!((s.normals[0][1] - Vec3::new(0.6, 0.0, 0.8)).length() < 1e-6);
        let flat = parse(&format!("{QUAD}f 1 2 3\n"), None).unwrap();
        assert!(flat.normals.is_empty());
    }

    #[test]
    fn bad_vertex_normals_fall_back_or_fail() {
        // Zero-length and NaN normals fall back to the geometric normal (+z).
        let s = parse(&format!("{QUAD}vn 0 0 0\nvn nan 0 1\nf 1//1 2//2 3//1\n"), None).unwrap();
        assert_eq!(s.normals[0], [Vec3::Z; 3]);
        s.validate().unwrap();
        // An index past the normals is an error, never a panic.
        let e = parse(&format!("{QUAD}vn 0 0 1\nf 1//1 2//7 3//1\n"), None);
        assert!(e.is_err(), "{e:?}");
    }

    #[test]
    fn specular_and_textured_materials_are_reported_not_rejected() {
        let mtl = "newmtl glossy\nKd 0.5 0.5 0.5\nKs 0.4 0.4 0.4\nNs 80\nnewmtl matte\nKd 0.5 0.5 0.5\nKs 0 0 0\nNs 10\nKa 1 1 1\nillum 2\nnewmtl tex\nKd 1 1 1\nmap_Kd wood.png\nd 0.5\n";
        let obj = format!("mtllib t.mtl\n{QUAD}usemtl glossy\nf 1 2 3\nusemtl matte\nf 1 3 4\n");
        let s = parse(&obj, Some(mtl)).unwrap();
        let by = |name: &str| s.unsupported.iter().find(|u| u.material == name).map(|u| u.features.clone());
        assert_eq!(by("glossy"), Some(vec!["Ks".to_string(), "Ns".to_string()]));
        assert_eq!(by("matte"), None);
        assert_eq!(by("tex"), Some(vec!["d".to_string(), "map_Kd".to_string()]));
        assert!(s.unsupported[0].message().contains("material 'glossy' has Ks, Ns"));
    }
}
