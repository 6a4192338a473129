//! OBJ + MTL loading through tobj: positions, per-corner normals (`vn`,
//! smooth shading), and materials ([`mtl_material`]: `Kd` base colour,
//! `Ks`/`Ns` or the PBR extension's `Pr`/`Pm` as glTF metallic-roughness,
//! `Ke` emission). MTL features the renderer does not model (`d`, `map_*`,
//! ...) are returned in [`Scene::unsupported`] for the caller to report.

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
/// transparency (with its index of refraction), texture maps, and keys
/// neither slc nor tobj knows. `Ka`, `illum` and the keys [`mtl_material`]
/// maps are silent.
fn unsupported_features(m: &tobj::Material) -> Vec<String> {
    let mut out = Vec::new();
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
    let mut unknown: Vec<&String> = m
        .unknown_param
        .keys()
        .filter(|k| !matches!(k.as_str(), "Tf" | "Ke" | "Pr" | "Pm"))
        .collect();
    unknown.sort();
    out.extend(unknown.into_iter().cloned());
    out
}

/// The slc material of an MTL material (`name` labels errors):
/// - `Kd` is the base colour (0.8 grey when absent), `Ke` the emission.
/// - With the PBR extension's `Pr` or `Pm` (Exocortex/Blender's MTL PBR
///   keys): glTF's metallic-roughness material, `Pr` its perceptual
///   roughness (`α = Pr²`; 1 when absent), `Pm` its metallic factor (0 when
///   absent), the dielectric's `F0 = ((Ni − 1)/(Ni + 1))²` (0.04 without
///   `Ni`) and `F90 = 1`; `Ks`/`Ns` are then ignored.
/// - Else a non-zero `Ks` (Blinn-Phong): a dielectric whose Fresnel is
///   `F0 = Ks`, `F90 = max(Ks)` (Phong's specular albedo, constant over
///   angles for a grey `Ks`), with the GGX `α = √(2/(Ns + 2))` of the
///   Blinn-Phong equivalence (Walter et al. 2007; `Ns` 0 when absent, so
///   `α = 1`), diffuse `Kd` weighted by `1 − F` as glTF's dielectric is.
/// - Else Lambertian: `f = Kd/π`.
pub fn mtl_material(m: &tobj::Material, name: &str) -> Result<Material, SceneError> {
    let kd = m.diffuse.map(Vec3::from).unwrap_or(Vec3::splat(0.8));
    let ke = m.emissive.map(Vec3::from).unwrap_or(Vec3::ZERO);
    let param = |key: &str| -> Result<Option<f32>, SceneError> {
        match m.unknown_param.get(key) {
            None => Ok(None),
            Some(v) => match v.trim().parse::<f32>() {
                Ok(x) if (0.0..=1.0).contains(&x) => Ok(Some(x)),
                _ => Err(SceneError::Obj(
                    name.to_string(),
                    format!("material '{}': {key} '{v}' must be a number in [0, 1]", m.name),
                )),
            },
        }
    };
    let (pr, pm) = (param("Pr")?, param("Pm")?);
    let ks = m.specular.map(Vec3::from).unwrap_or(Vec3::ZERO);
    let mut mat = if pr.is_some() || pm.is_some() {
        let f0 = match m.optical_density {
            Some(ni) if ni.is_finite() && ni >= 1.0 => ((ni - 1.0) / (ni + 1.0)).powi(2),
            Some(ni) => {
                return Err(SceneError::Obj(
                    name.to_string(),
                    format!("material '{}': Ni {ni} must be finite and >= 1", m.name),
                ));
            }
            None => 0.04,
        };
        Material { f0: Vec3::splat(f0), ..Material::gltf(kd, pm.unwrap_or(0.0), pr.unwrap_or(1.0)) }
    } else if ks.max_element() > 0.0 {
        let ns = m.shininess.unwrap_or(0.0);
        if !ns.is_finite() {
            return Err(SceneError::Obj(
                name.to_string(),
                format!("material '{}': Ns {ns} must be finite", m.name),
            ));
        }
        let alpha = (2.0 / (ns.max(0.0) + 2.0)).sqrt();
        Material { f0: ks, f90: ks.max_element(), ..Material::gltf(kd, 0.0, alpha.sqrt()) }
    } else {
        Material::lambertian(kd, Vec3::ZERO)
    };
    mat.emission = ke;
    Ok(mat)
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
        let text = std::fs::read(path)
            .map_err(|e| SceneError::Io(path.display().to_string(), e.to_string()))?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let name = path.display().to_string();
        Self::parse_obj(&text, &name, |p| {
            let direct = dir.join(p);
            let fallback = p.file_name().map(|f| dir.join(f));
            let chosen = if direct.exists() {
                direct
            } else {
                fallback.filter(|f| f.exists()).unwrap_or(direct)
            };
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
    pub fn parse_obj(
        obj: &[u8],
        name: &str,
        mtl: impl Fn(&Path) -> Option<Vec<u8>>,
    ) -> Result<Scene, SceneError> {
        let path = Path::new(name);
        let err = |what: String| SceneError::Obj(path.display().to_string(), what);
        let opts = tobj::LoadOptions {
            triangulate: true,
            single_index: false,
            ignore_points: true,
            ignore_lines: true,
        };
        let (models, mats) = tobj::load_obj_buf(&mut &obj[..], &opts, |p| match mtl(p) {
            Some(b) if short_colour_line(&b) => Err(tobj::LoadError::MaterialParseError),
            Some(b) => tobj::load_mtl_buf(&mut b.as_slice()),
            None => Err(tobj::LoadError::OpenFileFailed),
        })
        .map_err(|e| err(e.to_string()))?;
        let mats = mats.map_err(|e| err(format!("material library: {e}")))?;
        let file =
            path.file_name().map_or_else(|| name.to_string(), |f| f.to_string_lossy().into_owned());
        let unsupported = mats
            .iter()
            .filter_map(|m| {
                let features = unsupported_features(m);
                (!features.is_empty()).then(|| Unsupported {
                    source: file.clone(),
                    material: m.name.clone(),
                    features,
                })
            })
            .collect();
        let mut materials: Vec<Material> =
            mats.iter().map(|m| mtl_material(m, name)).collect::<Result<_, _>>()?;
        let default_mat = materials.len() as u32;
        materials.push(Material::lambertian(Vec3::splat(0.8), Vec3::ZERO));
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
                                .ok_or_else(|| {
                                    err(format!("normal index {} out of range", i / 3))
                                })?;
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
        let s = parse(
            &format!("{QUAD}vn 0 0 2\nvn 0.6 0 0.8\nf 1//1 2//2 3//1\nf 1//1 3//1 4//2\n"),
            None,
        )
        .unwrap();
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
    fn textured_and_transparent_materials_are_reported_not_rejected() {
        let mtl = "newmtl glossy\nKd 0.5 0.5 0.5\nKs 0.4 0.4 0.4\nNs 80\nnewmtl matte\nKd 0.5 0.5 0.5\nKs 0 0 0\nNs 10\nKa 1 1 1\nillum 2\nnewmtl tex\nKd 1 1 1\nmap_Kd wood.png\nd 0.5\nPs 0.3\n";
        let obj = format!("mtllib t.mtl\n{QUAD}usemtl glossy\nf 1 2 3\nusemtl matte\nf 1 3 4\n");
        let s = parse(&obj, Some(mtl)).unwrap();
        let by = |name: &str| {
            s.unsupported.iter().find(|u| u.material == name).map(|u| u.features.clone())
        };
        assert_eq!(by("glossy"), None);
        assert_eq!(by("matte"), None);
        assert_eq!(by("tex"), Some(vec!["d".to_string(), "map_Kd".to_string(), "Ps".to_string()]));
        assert!(s.unsupported[0].message().contains("material 'tex' has d, map_Kd, Ps"));
    }

    /// `Ks`/`Ns` become a glossy dielectric, `Pr`/`Pm` glTF's factors, and
    /// a `Kd`-only material stays exactly Lambertian.
    #[test]
    fn mtl_keys_map_to_metallic_roughness() {
        let mtl = "newmtl phong\nKd 0.2 0.3 0.4\nKs 0.9 0.9 0.9\nNs 60\n\
                   newmtl pbr\nKd 0.9 0.6 0.3\nPr 0.25\nPm 1\nKs 0.5 0.5 0.5\n\
                   newmtl ior\nKd 0.5 0.5 0.5\nPr 0.5\nNi 2.0\n\
                   newmtl matte\nKd 0.5 0.5 0.5\nKe 1 2 3\n";
        let obj = format!(
            "mtllib t.mtl\n{QUAD}usemtl phong\nf 1 2 3\nusemtl pbr\nf 1 3 4\nusemtl ior\nf 1 2 4\nusemtl matte\nf 2 3 4\n"
        );
        let s = parse(&obj, Some(mtl)).unwrap();
        let [phong, pbr, ior, matte] = [0, 1, 2, 3].map(|i| s.materials[i]);
        // α = √(2/62) for Ns 60; roughness = √α.
        assert!((phong.alpha() - (2.0f32 / 62.0).sqrt()).abs() < 1e-6, "{}", phong.alpha());
        assert_eq!(
            (phong.f0, phong.f90, phong.metallic, phong.albedo),
            (Vec3::splat(0.9), 0.9, 0.0, Vec3::new(0.2, 0.3, 0.4))
        );
        assert!(phong.has_specular());
        assert_eq!(
            (pbr.metallic, pbr.roughness, pbr.f0, pbr.f90),
            (1.0, 0.25, Vec3::splat(0.04), 1.0)
        );
        assert!((ior.f0.x - 1.0 / 9.0).abs() < 1e-6 && ior.metallic == 0.0);
        assert_eq!(matte, Material::lambertian(Vec3::splat(0.5), Vec3::new(1.0, 2.0, 3.0)));
        assert!(!matte.has_specular());
        // Out-of-range PBR keys are errors naming the key.
        for bad in ["Pr 1.5", "Pm -0.1", "Pr nan", "Pm x"] {
            let e = parse(
                &format!("mtllib t.mtl\n{QUAD}usemtl m\nf 1 2 3\n"),
                Some(&format!("newmtl m\nKd 1 1 1\n{bad}\n")),
            );
            let key = &bad[..2];
            assert!(
                matches!(&e, Err(SceneError::Obj(_, what)) if what.contains(key)),
                "{bad}: {e:?}"
            );
        }
    }
}
