//! glTF 2.0 loading through the `gltf` crate (`.gltf` with external or
//! embedded buffers, and `.glb`):
//!
//! - **Meshes** of the default scene (or the first), with their nodes'
//!   transforms: triangle primitives (`TRIANGLES`, `TRIANGLE_STRIP`,
//!   `TRIANGLE_FAN`), indexed or not, `POSITION` and `NORMAL` (normals go
//!   through the inverse transpose; a mesh without them is flat-shaded).
//! - **Materials**: metallic-roughness factors ([`Material`]: base colour,
//!   metallic, perceptual roughness), `KHR_materials_ior` (the dielectric's
//!   `F0 = ((ior − 1)/(ior + 1))²`), `KHR_materials_specular` (`F0` times
//!   the specular colour, capped at 1, both `F0` and `F90` times the
//!   specular factor), emission (`emissiveFactor` ×
//!   `KHR_materials_emissive_strength`): emissive triangles become triangle
//!   lights, one-sided along their counter-clockwise normal, as glTF's front
//!   face. A primitive without a material gets glTF's default (white metal,
//!   roughness 1). Textures (base colour, metallic-roughness, normal,
//!   occlusion, emissive), vertex colours, alpha blending and masking,
//!   transmission and volume are reported in [`Scene::unsupported`], one
//!   line per material; the factors are used.
//! - **Lights** (`KHR_lights_punctual`): point and spot lights become
//!   [`Light::Point`] and [`Light::Spot`] with intensity `colour ×
//!   intensity` (candela taken as the scene's intensity unit, `range`
//!   ignored: stochastic light culling needs no hard range); slc's spot
//!   fall-off is a smoothstep between the cone angles where glTF's is the
//!   square of a linear ramp. The first spot light (else the first
//!   directional light) is also the VPL application's primary light; a
//!   directional light is not a path-tracer light and is reported.
//! - **Camera**: the first perspective camera met in the scene's nodes
//!   (`yfov`; looking down its node's −z with +y up); without one the
//!   bounds are framed as for an OBJ.
//!
//! Bad files are typed errors, never panics: a truncated GLB, a buffer
//! shorter than declared, an accessor outside its buffer view or of the
//! wrong type, an index past the vertices, NaN or out-of-range factors, a
//! node hierarchy deeper than [`MAX_NODE_DEPTH`].

use crate::SceneError;
use crate::scene::{Camera, Material, PrimaryLight, Scene, Unsupported};
use glam::{Mat3, Mat4, Vec3};
use gltf::accessor::{DataType, Dimensions};
use gltf::khr_lights_punctual::Kind;
use gltf::mesh::Mode;
use slc_core::light::{Light, PointLight, SpotLight};
use std::path::Path;

/// The deepest node hierarchy read (a cycle, which glTF forbids, is caught
/// by this bound).
pub const MAX_NODE_DEPTH: usize = 64;

/// A loaded glTF scene: its geometry, materials, camera and primary light,
/// and its punctual lights (for the path tracer).
#[derive(Clone, Debug)]
pub struct GltfScene {
    /// Geometry (emissive triangles included), camera and primary light.
    pub scene: Scene,
    /// Point and spot lights of `KHR_lights_punctual`.
    pub lights: Vec<Light>,
}

impl GltfScene {
    /// Reads a `.gltf` (buffers beside it, or embedded as data URIs) or
    /// `.glb` file.
    pub fn load(path: &Path) -> Result<GltfScene, SceneError> {
        let bytes = std::fs::read(path)
            .map_err(|e| SceneError::Io(path.display().to_string(), e.to_string()))?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Self::parse(&bytes, &path.display().to_string(), |p| std::fs::read(dir.join(p)).ok())
    }

    /// Parses glTF JSON or GLB bytes; `resolve(path)` returns the bytes of
    /// an external buffer the file names (relative to it), or `None`.
    /// `name` labels errors and the scene.
    pub fn parse(
        bytes: &[u8],
        name: &str,
        resolve: impl Fn(&Path) -> Option<Vec<u8>>,
    ) -> Result<GltfScene, SceneError> {
        let err = |what: String| SceneError::Gltf(name.to_string(), what);
        let gltf::Gltf { document, blob } =
            gltf::Gltf::from_slice(bytes).map_err(|e| err(e.to_string()))?;
        let buffers = load_buffers(&document, blob, &resolve).map_err(err)?;
        let file = Path::new(name)
            .file_name()
            .map_or_else(|| name.to_string(), |f| f.to_string_lossy().into_owned());
        let mut b = Builder {
            buffers,
            triangles: Vec::new(),
            normals: Vec::new(),
            prim_features: Vec::new(),
            material_of: Vec::new(),
            camera: None,
            lights: Vec::new(),
            spot: None,
            sun: None,
        };
        let mut unsupported = Vec::new();
        let mut materials = Vec::new();
        for (i, m) in document.materials().enumerate() {
            let label = m.name().map_or_else(|| format!("#{i}"), str::to_string);
            let (mat, features) =
                material(&m).map_err(|e| err(format!("material '{label}': {e}")))?;
            materials.push(mat);
            if !features.is_empty() {
                unsupported.push(Unsupported { source: file.clone(), material: label, features });
            }
        }
        let default_material = materials.len() as u32;
        materials.push(Material::gltf(Vec3::ONE, 1.0, 1.0));
        let scene = document
            .default_scene()
            .or_else(|| document.scenes().next())
            .ok_or_else(|| err("the file has no scene".into()))?;
        for node in scene.nodes() {
            b.node(&node, Mat4::IDENTITY, 0, default_material).map_err(err)?;
        }
        let lights_off = b.lights.iter().filter(|(_, kind)| *kind == "directional").count();
        if lights_off > 0 {
            unsupported.push(Unsupported {
                source: file.clone(),
                material: format!("{lights_off} directional light(s)"),
                features: vec!["KHR_lights_punctual directional (the path tracer has no directional light; the first lights the VPL application as its primary light)".into()],
            });
        }
        let mut out = Scene {
            name: Path::new(name)
                .file_stem()
                .map_or("gltf".into(), |s| s.to_string_lossy().into_owned()),
            triangles: b.triangles,
            normals: Vec::new(),
            material_of: b.material_of,
            materials,
            camera: Camera { position: Vec3::Z, target: Vec3::ZERO, up: Vec3::Y, vfov_deg: 40.0 },
            primary: PrimaryLight::Directional { direction: -Vec3::Y, irradiance: Vec3::ONE },
            unsupported,
        };
        if out.triangles.is_empty() {
            return Err(SceneError::Empty);
        }
        // Vertex normals for all, the geometric ones where a primitive has
        // none; no array at all when no primitive has any.
        out.normals = if b.normals.iter().all(Option::is_none) {
            Vec::new()
        } else {
            b.normals
                .iter()
                .enumerate()
                .map(|(i, ns)| ns.unwrap_or([out.geometric_normal(i); 3]))
                .collect()
        };
        if !b.prim_features.is_empty() {
            out.unsupported.push(Unsupported {
                source: file.clone(),
                material: "primitives".into(),
                features: b.prim_features,
            });
        }
        out.frame_default_view();
        if let Some(c) = b.camera {
            out.camera = c;
        }
        if let Some(p) = b.spot.or(b.sun) {
            out.primary = p;
        }
        out.validate()?;
        Ok(GltfScene { scene: out, lights: b.lights.into_iter().filter_map(|(l, _)| l).collect() })
    }
}

/// The bytes of every buffer: the GLB's binary chunk, a base64 data URI,
/// or an external file; each at least as long as it declares.
fn load_buffers(
    doc: &gltf::Document,
    mut blob: Option<Vec<u8>>,
    resolve: &impl Fn(&Path) -> Option<Vec<u8>>,
) -> Result<Vec<Vec<u8>>, String> {
    use base64::Engine;
    let mut out = Vec::new();
    for buffer in doc.buffers() {
        let data = match buffer.source() {
            gltf::buffer::Source::Bin => blob.take().ok_or_else(|| {
                format!("buffer {} names the GLB's binary chunk, which is missing", buffer.index())
            })?,
            gltf::buffer::Source::Uri(uri) => {
                if let Some(rest) = uri.strip_prefix("data:") {
                    let (_, payload) = rest.split_once(";base64,").ok_or_else(|| {
                        format!("buffer {}: only base64 data URIs are read", buffer.index())
                    })?;
                    base64::engine::general_purpose::STANDARD
                        .decode(payload)
                        .map_err(|e| format!("buffer {}: bad base64 ({e})", buffer.index()))?
                } else {
                    let path = urlencoding::decode(uri)
                        .map_err(|e| format!("buffer {}: bad URI '{uri}' ({e})", buffer.index()))?;
                    resolve(Path::new(path.as_ref()))
                        .ok_or_else(|| format!("buffer {}: cannot read '{path}'", buffer.index()))?
                }
            }
        };
        if data.len() < buffer.length() {
            return Err(format!(
                "buffer {} holds {} bytes, fewer than the {} it declares",
                buffer.index(),
                data.len(),
                buffer.length()
            ));
        }
        out.push(data);
    }
    Ok(out)
}

/// Checks that `acc` is a dense accessor of `dims` and one of `types` whose
/// elements all lie inside its buffer view and buffer, so that the `gltf`
/// crate's reader (which asserts these in debug builds) can read it.
fn check_accessor(
    acc: &gltf::Accessor,
    what: &str,
    dims: Dimensions,
    types: &[DataType],
    buffers: &[Vec<u8>],
) -> Result<(), String> {
    let bad = |why: String| Err(format!("{what} accessor {}: {why}", acc.index()));
    if acc.dimensions() != dims || !types.contains(&acc.data_type()) {
        return bad(format!(
            "{:?} of {:?} where {dims:?} of {types:?} is needed",
            acc.dimensions(),
            acc.data_type()
        ));
    }
    if acc.sparse().is_some() {
        return bad("sparse accessors are not read".into());
    }
    if acc.normalized() {
        return bad("normalized integers are not read".into());
    }
    let Some(view) = acc.view() else { return bad("no buffer view".into()) };
    let size = acc.size();
    let stride = view.stride().unwrap_or(size);
    if acc.count() == 0 || stride < size {
        return bad(format!("count {} and stride {stride} (element {size} bytes)", acc.count()));
    }
    let end = (acc.count() - 1)
        .checked_mul(stride)
        .and_then(|x| x.checked_add(acc.offset()))
        .and_then(|x| x.checked_add(size));
    let view_end = view.offset().checked_add(view.length());
    match (end, view_end) {
        (Some(e), Some(ve)) if e <= view.length() && ve <= buffers[view.buffer().index()].len() => {
            Ok(())
        }
        _ => bad("reads past its buffer view or buffer".into()),
    }
}

/// What the node walk collects.
struct Builder {
    buffers: Vec<Vec<u8>>,
    triangles: Vec<[Vec3; 3]>,
    /// Vertex normals per triangle (`None` where the primitive has none).
    normals: Vec<Option<[Vec3; 3]>>,
    /// Primitive attributes slc ignores (`COLOR_0`, ...), once each.
    prim_features: Vec<String>,
    material_of: Vec<u32>,
    camera: Option<Camera>,
    /// Every punctual light with its kind (`None` for a directional one).
    lights: Vec<(Option<Light>, &'static str)>,
    spot: Option<PrimaryLight>,
    sun: Option<PrimaryLight>,
}

impl Builder {
    fn node(
        &mut self,
        node: &gltf::Node,
        parent: Mat4,
        depth: usize,
        default_material: u32,
    ) -> Result<(), String> {
        if depth >= MAX_NODE_DEPTH {
            return Err(format!(
                "node {} is deeper than {MAX_NODE_DEPTH} levels (a cycle?)",
                node.index()
            ));
        }
        let local = Mat4::from_cols_array_2d(&node.transform().matrix());
        let world = parent * local;
        if !world.is_finite() {
            return Err(format!("node {}: its transform is not finite", node.index()));
        }
        if let Some(mesh) = node.mesh() {
            for prim in mesh.primitives() {
                self.primitive(&prim, world, default_material).map_err(|e| {
                    format!("mesh {} primitive {}: {e}", mesh.index(), prim.index())
                })?;
            }
        }
        let origin = world.transform_point3(Vec3::ZERO);
        let axis = world.transform_vector3(-Vec3::Z).normalize_or_zero();
        if let Some(cam) = node.camera()
            && self.camera.is_none()
            && let gltf::camera::Projection::Perspective(p) = cam.projection()
        {
            let up = world.transform_vector3(Vec3::Y).normalize_or_zero();
            let vfov_deg = p.yfov().to_degrees();
            if !(vfov_deg > 0.0 && vfov_deg < 180.0) || axis == Vec3::ZERO || up == Vec3::ZERO {
                return Err(format!(
                    "camera {}: yfov {} rad or its node's axes are unusable",
                    cam.index(),
                    p.yfov()
                ));
            }
            self.camera = Some(Camera { position: origin, target: origin + axis, up, vfov_deg });
        }
        if let Some(light) = node.light() {
            self.light(&light, origin, axis)?;
        }
        for child in node.children() {
            self.node(&child, world, depth + 1, default_material)?;
        }
        Ok(())
    }

    fn light(
        &mut self,
        light: &gltf::khr_lights_punctual::Light,
        origin: Vec3,
        axis: Vec3,
    ) -> Result<(), String> {
        let what = format!("light {}", light.index());
        let intensity = Vec3::from(light.color()) * light.intensity();
        if !(intensity.is_finite() && intensity.min_element() >= 0.0) {
            return Err(format!("{what}: colour × intensity {intensity} must be finite and >= 0"));
        }
        match light.kind() {
            Kind::Point => {
                let l = PointLight::new(origin, intensity).map_err(|e| format!("{what}: {e}"))?;
                self.lights.push((Some(Light::Point(l)), "point"));
            }
            Kind::Spot { inner_cone_angle, outer_cone_angle } => {
                let s = SpotLight::new(origin, axis, intensity, inner_cone_angle, outer_cone_angle)
                    .map_err(|e| format!("{what}: {e}"))?;
                self.lights.push((Some(Light::Spot(s)), "spot"));
                if self.spot.is_none() && outer_cone_angle < 85f32.to_radians() {
                    self.spot = Some(PrimaryLight::Spot {
                        position: origin,
                        direction: axis,
                        intensity,
                        inner: inner_cone_angle,
                        outer: outer_cone_angle,
                    });
                }
            }
            Kind::Directional => {
                self.lights.push((None, "directional"));
                if self.sun.is_none() && axis != Vec3::ZERO {
                    self.sun =
                        Some(PrimaryLight::Directional { direction: axis, irradiance: intensity });
                }
            }
        }
        Ok(())
    }

    fn primitive(
        &mut self,
        prim: &gltf::Primitive,
        world: Mat4,
        default_material: u32,
    ) -> Result<(), String> {
        let mode = prim.mode();
        if !matches!(mode, Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan) {
            return Ok(()); // Points and lines have no area.
        }
        for (sem, _) in prim.attributes() {
            let name = match sem {
                gltf::Semantic::Colors(i) => format!("COLOR_{i}"),
                gltf::Semantic::Joints(_) | gltf::Semantic::Weights(_) => "skinning".into(),
                _ => continue,
            };
            if !self.prim_features.contains(&name) {
                self.prim_features.push(name);
            }
        }
        if prim.morph_targets().len() > 0
            && !self.prim_features.iter().any(|f| f == "morph targets")
        {
            self.prim_features.push("morph targets".into());
        }
        let pos = prim.get(&gltf::Semantic::Positions).ok_or("no POSITION")?;
        check_accessor(&pos, "POSITION", Dimensions::Vec3, &[DataType::F32], &self.buffers)?;
        let reader = prim.reader(|b| self.buffers.get(b.index()).map(Vec::as_slice));
        let positions: Vec<Vec3> = reader
            .read_positions()
            .ok_or("POSITION cannot be read")?
            .map(|p| world.transform_point3(Vec3::from(p)))
            .collect();
        let normals: Option<Vec<Vec3>> = match prim.get(&gltf::Semantic::Normals) {
            Some(acc) => {
                check_accessor(&acc, "NORMAL", Dimensions::Vec3, &[DataType::F32], &self.buffers)?;
                if acc.count() != pos.count() {
                    return Err(format!("{} normals for {} positions", acc.count(), pos.count()));
                }
                let m = Mat3::from_mat4(world).inverse().transpose();
                Some(
                    reader
                        .read_normals()
                        .ok_or("NORMAL cannot be read")?
                        .map(|n| (m * Vec3::from(n)).normalize_or_zero())
                        .collect(),
                )
            }
            None => None,
        };
        let indices: Vec<u32> = match prim.indices() {
            Some(acc) => {
                check_accessor(
                    &acc,
                    "index",
                    Dimensions::Scalar,
                    &[DataType::U8, DataType::U16, DataType::U32],
                    &self.buffers,
                )?;
                reader.read_indices().ok_or("indices cannot be read")?.into_u32().collect()
            }
            None => (0..positions.len() as u32).collect(),
        };
        if let Some(&i) = indices.iter().find(|&&i| i as usize >= positions.len()) {
            return Err(format!("index {i} past the {} vertices", positions.len()));
        }
        let corners: Vec<[u32; 3]> = match mode {
            Mode::Triangles => indices.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect(),
            // Strips alternate their winding so every triangle faces the same way.
            Mode::TriangleStrip => indices
                .windows(3)
                .enumerate()
                .map(|(k, w)| if k % 2 == 0 { [w[0], w[1], w[2]] } else { [w[1], w[0], w[2]] })
                .collect(),
            _ => indices.windows(2).skip(1).map(|w| [indices[0], w[0], w[1]]).collect(),
        };
        let material = prim.material().index().map_or(default_material, |i| i as u32);
        for [a, b, c] in corners {
            let tri = [positions[a as usize], positions[b as usize], positions[c as usize]];
            self.triangles.push(tri);
            self.material_of.push(material);
            let geometric = slc_core::ray::triangle_normal(tri[0], tri[1], tri[2]);
            // A zero or non-finite normal falls back to the geometric one (a
            // degenerate triangle's is any unit vector: it is never hit).
            self.normals.push(normals.as_ref().map(|ns| {
                [a, b, c].map(|i| {
                    let n = ns[i as usize];
                    if n.is_finite() && n != Vec3::ZERO {
                        n
                    } else if geometric != Vec3::ZERO {
                        geometric
                    } else {
                        Vec3::Y
                    }
                })
            }));
        }
        Ok(())
    }
}

/// The slc material of a glTF material and the features of it that slc
/// ignores.
fn material(m: &gltf::Material) -> Result<(Material, Vec<String>), String> {
    let pbr = m.pbr_metallic_roughness();
    let [r, g, b, _] = pbr.base_color_factor();
    let base = Vec3::new(r, g, b);
    let ior = m.ior().unwrap_or(1.5);
    if !(ior.is_finite() && ior >= 1.0) {
        return Err(format!("ior {ior} must be finite and >= 1"));
    }
    let mut f0 = Vec3::splat(((ior - 1.0) / (ior + 1.0)).powi(2));
    let mut f90 = 1.0;
    if let Some(s) = m.specular() {
        let (factor, colour) = (s.specular_factor(), Vec3::from(s.specular_color_factor()));
        if !(factor.is_finite()
            && (0.0..=1.0).contains(&factor)
            && colour.is_finite()
            && colour.min_element() >= 0.0)
        {
            return Err(format!(
                "KHR_materials_specular factor {factor} must be in [0, 1] and colour {colour} finite and >= 0"
            ));
        }
        f0 = (f0 * colour).min(Vec3::ONE) * factor;
        f90 = factor;
    }
    let emission = Vec3::from(m.emissive_factor()) * m.emissive_strength().unwrap_or(1.0);
    let mat = Material {
        albedo: base,
        emission,
        metallic: pbr.metallic_factor(),
        roughness: pbr.roughness_factor(),
        f0,
        f90,
    };
    mat.validate(m.index().unwrap_or(0)).map_err(|e| e.to_string())?;
    let mut features = Vec::new();
    let mut flag = |on: bool, what: &str| {
        if on {
            features.push(what.to_string());
        }
    };
    flag(pbr.base_color_texture().is_some(), "baseColorTexture");
    flag(pbr.metallic_roughness_texture().is_some(), "metallicRoughnessTexture");
    flag(m.normal_texture().is_some(), "normalTexture");
    flag(m.occlusion_texture().is_some(), "occlusionTexture");
    flag(m.emissive_texture().is_some(), "emissiveTexture");
    flag(m.alpha_mode() != gltf::material::AlphaMode::Opaque, "alphaMode");
    flag(m.transmission().is_some(), "KHR_materials_transmission");
    flag(m.volume().is_some(), "KHR_materials_volume");
    flag(
        m.specular().is_some_and(|s| {
            s.specular_texture().is_some() || s.specular_color_texture().is_some()
        }),
        "specular textures",
    );
    if let Some(ext) = m.extensions() {
        for k in ext.keys() {
            if !matches!(
                k.as_str(),
                "KHR_materials_ior"
                    | "KHR_materials_specular"
                    | "KHR_materials_emissive_strength"
                    | "KHR_materials_transmission"
                    | "KHR_materials_volume"
            ) {
                features.push(k.clone());
            }
        }
    }
    Ok((mat, features))
}

#[cfg(test)]
mod tests {
    use super::*;
    use base64::Engine;
    use serde_json::{Value, json};

    /// A little glTF writer: a buffer built from typed arrays, accessors
    /// over it, and the rest of the document given as JSON.
    struct Doc {
        bin: Vec<u8>,
        views: Vec<Value>,
        accessors: Vec<Value>,
    }

    impl Doc {
        fn new() -> Doc {
            Doc { bin: Vec::new(), views: Vec::new(), accessors: Vec::new() }
        }
        /// Appends `bytes` as a buffer view and an accessor of `count`
        /// elements of `ty` / `component`; returns the accessor's index.
        fn accessor(&mut self, bytes: &[u8], count: usize, ty: &str, component: u32) -> usize {
            while !self.bin.len().is_multiple_of(4) {
                self.bin.push(0);
            }
            self.views.push(
                json!({ "buffer": 0, "byteOffset": self.bin.len(), "byteLength": bytes.len() }),
            );
            self.bin.extend_from_slice(bytes);
            self.accessors.push(json!({ "bufferView": self.views.len() - 1, "count": count, "type": ty, "componentType": component }));
            self.accessors.len() - 1
        }
        /// A VEC3 accessor with the `min`/`max` glTF requires of positions.
        fn vec3s(&mut self, v: &[[f32; 3]]) -> usize {
            let bytes: Vec<u8> = v.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
            let a = self.accessor(&bytes, v.len(), "VEC3", 5126);
            let (lo, hi) = v.iter().fold(([f32::MAX; 3], [f32::MIN; 3]), |(lo, hi), p| {
                ([0, 1, 2].map(|k| lo[k].min(p[k])), [0, 1, 2].map(|k| hi[k].max(p[k])))
            });
            self.accessors[a]["min"] = json!(lo);
            self.accessors[a]["max"] = json!(hi);
            a
        }
        fn u16s(&mut self, v: &[u16]) -> usize {
            let bytes: Vec<u8> = v.iter().flat_map(|x| x.to_le_bytes()).collect();
            self.accessor(&bytes, v.len(), "SCALAR", 5123)
        }
        /// The whole document as glTF JSON with the buffer as a data URI;
        /// `rest` holds meshes, materials, nodes, scenes, ...
        fn json(&self, mut rest: Value) -> Vec<u8> {
            let uri = format!(
                "data:application/octet-stream;base64,{}",
                base64::engine::general_purpose::STANDARD.encode(&self.bin)
            );
            let o = rest.as_object_mut().unwrap();
            o.insert("asset".into(), json!({ "version": "2.0" }));
            o.insert("buffers".into(), json!([{ "byteLength": self.bin.len(), "uri": uri }]));
            o.insert("bufferViews".into(), Value::Array(self.views.clone()));
            o.insert("accessors".into(), Value::Array(self.accessors.clone()));
            serde_json::to_vec(&rest).unwrap()
        }
        /// The same as GLB, the buffer in its binary chunk.
        fn glb(&self, mut rest: Value) -> Vec<u8> {
            let o = rest.as_object_mut().unwrap();
            o.insert("asset".into(), json!({ "version": "2.0" }));
            o.insert("buffers".into(), json!([{ "byteLength": self.bin.len() }]));
            o.insert("bufferViews".into(), Value::Array(self.views.clone()));
            o.insert("accessors".into(), Value::Array(self.accessors.clone()));
            let mut js = serde_json::to_vec(&rest).unwrap();
            while !js.len().is_multiple_of(4) {
                js.push(b' ');
            }
            let mut bin = self.bin.clone();
            while !bin.len().is_multiple_of(4) {
                bin.push(0);
            }
            let total = 12 + 8 + js.len() + 8 + bin.len();
            let mut out = Vec::new();
            out.extend_from_slice(b"glTF");
            out.extend_from_slice(&2u32.to_le_bytes());
            out.extend_from_slice(&(total as u32).to_le_bytes());
            out.extend_from_slice(&(js.len() as u32).to_le_bytes());
            out.extend_from_slice(b"JSON");
            out.extend_from_slice(&js);
            out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
            out.extend_from_slice(b"BIN\0");
            out.extend_from_slice(&bin);
            out
        }
    }

    /// A floor quad (material 0), an emissive triangle above it (material 1)
    /// under a node that scales and moves it, a camera, and a point, a spot
    /// and a directional light.
    fn room() -> (Doc, Value) {
        let mut d = Doc::new();
        let quad =
            d.vec3s(&[[-1.0, 0.0, -1.0], [1.0, 0.0, -1.0], [1.0, 0.0, 1.0], [-1.0, 0.0, 1.0]]);
        let up = d.vec3s(&[[0.0, 1.0, 0.0]; 4]);
        let idx = d.u16s(&[0, 2, 1, 0, 3, 2]);
        let tri = d.vec3s(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]);
        let rest = json!({
            "scene": 0,
            "scenes": [{ "nodes": [0, 1, 2, 3] }],
            "nodes": [
                { "mesh": 0 },
                { "mesh": 1, "translation": [0.0, 2.0, 0.0], "scale": [0.5, 0.5, 0.5] },
                { "camera": 0, "translation": [0.0, 1.0, 5.0] },
                { "children": [4, 5, 6], "translation": [0.0, 3.0, 0.0] },
                { "extensions": { "KHR_lights_punctual": { "light": 0 } } },
                { "extensions": { "KHR_lights_punctual": { "light": 1 } }, "rotation": [-0.70710677, 0.0, 0.0, 0.70710677] },
                { "extensions": { "KHR_lights_punctual": { "light": 2 } } }
            ],
            "meshes": [
                { "primitives": [{ "attributes": { "POSITION": quad, "NORMAL": up }, "indices": idx, "material": 0 }] },
                { "primitives": [{ "attributes": { "POSITION": tri }, "material": 1 }] }
            ],
            "materials": [
                { "name": "gold", "pbrMetallicRoughness": { "baseColorFactor": [1.0, 0.8, 0.3, 1.0], "metallicFactor": 1.0, "roughnessFactor": 0.3 },
                  "extensions": { "KHR_materials_ior": { "ior": 1.8 } } },
                { "name": "lamp", "emissiveFactor": [1.0, 0.5, 0.25], "extensions": { "KHR_materials_emissive_strength": { "emissiveStrength": 4.0 } },
                  "pbrMetallicRoughness": { "metallicFactor": 0.0 } }
            ],
            "cameras": [{ "type": "perspective", "perspective": { "yfov": 0.7, "znear": 0.1 } }],
            "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_ior", "KHR_materials_emissive_strength"],
            "extensions": { "KHR_lights_punctual": { "lights": [
                { "type": "point", "color": [1.0, 0.5, 0.5], "intensity": 10.0, "range": 2.0 },
                { "type": "spot", "intensity": 5.0, "spot": { "innerConeAngle": 0.2, "outerConeAngle": 0.6 } },
                { "type": "directional", "intensity": 3.0 }
            ] } }
        });
        (d, rest)
    }

    fn parse(bytes: &[u8]) -> Result<GltfScene, SceneError> {
        GltfScene::parse(bytes, "t.gltf", |_| None)
    }

    #[test]
    fn meshes_materials_camera_and_lights_are_read() {
        let (d, rest) = room();
        for bytes in [d.json(rest.clone()), d.glb(rest)] {
            let g = parse(&bytes).unwrap();
            let s = &g.scene;
            assert_eq!(s.triangles.len(), 3);
            // The quad's winding (0, 2, 1) faces +y; the emitter is scaled by ½ and raised by 2.
            assert!(s.geometric_normal(0).abs_diff_eq(Vec3::Y, 1e-6));
            assert_eq!(
                s.triangles[2],
                [Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.5, 2.0, 0.0), Vec3::new(0.0, 2.0, 0.5)]
            );
            // Vertex normals where given, geometric ones for the emitter.
            assert_eq!(s.normals[0], [Vec3::Y; 3]);
            assert_eq!(s.normals[2], [s.geometric_normal(2); 3]);
            let gold = s.materials[s.material_of[0] as usize];
            assert_eq!(
                (gold.albedo, gold.metallic, gold.roughness, gold.f90),
                (Vec3::new(1.0, 0.8, 0.3), 1.0, 0.3, 1.0)
            );
            assert!((gold.f0.x - (0.8f32 / 2.8).powi(2)).abs() < 1e-6);
            let lamp = s.materials[s.material_of[2] as usize];
            assert_eq!(lamp.emission, Vec3::new(4.0, 2.0, 1.0));
            assert_eq!((lamp.metallic, lamp.roughness, lamp.albedo), (0.0, 1.0, Vec3::ONE));
            assert_eq!(s.camera.position, Vec3::new(0.0, 1.0, 5.0));
            assert!(
                (s.camera.target - Vec3::new(0.0, 1.0, 4.0)).length() < 1e-6
                    && (s.camera.vfov_deg - 0.7f32.to_degrees()).abs() < 1e-4
            );
            // The point light at the group's origin, the spot turned to look down.
            assert_eq!(g.lights.len(), 2);
            let Light::Point(p) = &g.lights[0] else { panic!("{:?}", g.lights[0]) };
            assert_eq!(
                (p.position(), g.lights[0].peak()),
                (Vec3::new(0.0, 3.0, 0.0), Vec3::new(10.0, 5.0, 5.0))
            );
            let Light::Spot(sp) = &g.lights[1] else { panic!("{:?}", g.lights[1]) };
            assert!(sp.direction().abs_diff_eq(-Vec3::Y, 1e-6), "{}", sp.direction());
            match s.primary {
                PrimaryLight::Spot { position, outer, .. } => {
                    assert!(position == Vec3::new(0.0, 3.0, 0.0) && outer == 0.6)
                }
                other => panic!("{other:?}"),
            }
            // The directional light is reported, not dropped silently.
            assert!(
                s.unsupported.iter().any(|u| u.features.iter().any(|f| f.contains("directional"))),
                "{:?}",
                s.unsupported
            );
        }
    }

    #[test]
    fn textures_and_colours_are_reported() {
        let (mut d, mut rest) = room();
        let colours = d.vec3s(&[[1.0, 0.0, 0.0]; 3]);
        rest["meshes"][1]["primitives"][0]["attributes"]["COLOR_0"] = json!(colours);
        rest["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = json!({ "index": 0 });
        rest["textures"] = json!([{ "source": 0 }]);
        rest["images"] = json!([{ "uri": "wood.png" }]);
        let s = parse(&d.json(rest)).unwrap().scene;
        let by =
            |m: &str| s.unsupported.iter().find(|u| u.material == m).map(|u| u.features.clone());
        assert_eq!(by("gold"), Some(vec!["baseColorTexture".to_string()]));
        assert_eq!(by("primitives"), Some(vec!["COLOR_0".to_string()]));
    }

    /// Bad files are typed errors that say what is wrong, never panics.
    #[test]
    fn bad_files_are_errors() {
        let err = |bytes: &[u8], want: &str| match parse(bytes) {
            Err(e) => assert!(e.to_string().contains(want), "expected '{want}' in: {e}"),
            Ok(_) => panic!("accepted; expected '{want}'"),
        };
        let (d, rest) = room();
        let glb = d.glb(rest.clone());
        for cut in [0, 11, 20, glb.len() / 2, glb.len() - 1] {
            assert!(matches!(parse(&glb[..cut]), Err(SceneError::Gltf(..))), "GLB cut at {cut}");
        }
        let mut r = rest.clone();
        r["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = json!(1.5);
        err(&d.json(r), "roughness 1.5");
        let mut r = rest.clone();
        r["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = json!([2.0, 0.0, 0.0, 1.0]);
        err(&d.json(r), "outside [0, 1]");
        let mut r = rest.clone();
        r["materials"][0]["extensions"]["KHR_materials_ior"]["ior"] = json!(0.5);
        err(&d.json(r), "ior 0.5");
        // An index past the four vertices.
        let (mut d2, mut r) = room();
        let bad = d2.u16s(&[0, 2, 9]);
        r["meshes"][0]["primitives"][0]["indices"] = json!(bad);
        err(&d2.json(r), "index 9");
        // An accessor that reads past its view; one of the wrong type.
        let mut d3 = room().0;
        d3.accessors[0]["count"] = json!(40);
        err(&d3.json(room().1), "past its buffer view");
        let mut d4 = room().0;
        d4.accessors[0]["type"] = json!("VEC2");
        err(&d4.json(room().1), "POSITION accessor 0");
        // A buffer shorter than it says.
        let mut js: Value = serde_json::from_slice(&d.json(rest.clone())).unwrap();
        js["buffers"][0]["byteLength"] = json!(10_000);
        err(&serde_json::to_vec(&js).unwrap(), "fewer than the 10000");
        // An external buffer that cannot be read.
        js["buffers"][0]["uri"] = json!("missing.bin");
        err(&serde_json::to_vec(&js).unwrap(), "cannot read 'missing.bin'");
        // A node that is its own child.
        let mut r = rest;
        r["nodes"][3]["children"] = json!([3]);
        assert!(parse(&d.json(r)).is_err());
        // Not glTF at all.
        err(b"{ not json", "invalid glTF");
    }
}
