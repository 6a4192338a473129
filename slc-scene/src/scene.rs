//! The scene model both backends take: triangles (with optional per-vertex
//! shading normals) with glTF metallic-roughness materials and emission, a pinhole camera and
//! the VPL application's primary light. Loaded from OBJ+MTL ([`crate::obj`]),
//! scene files ([`crate::scene_file`]) or built in ([`crate::cornell`]).

use crate::SceneError;
use glam::Vec3;
use slc_core::importance::Receiver;
use slc_core::light::SpotLight;

/// A glTF 2.0 metallic-roughness material with emission, as
/// [`slc_core::brdf`] evaluates it: `f = mix(dielectric, metal, metallic)`
/// with a Lambertian diffuse lobe and a GGX specular lobe of `α =
/// roughness²`. [`Material::lambertian`] (no specular lobe: `f = albedo/π`)
/// is what the OBJ loader makes of a diffuse MTL material and what the
/// built-in Cornell box uses; [`Material::gltf`] is glTF's dielectric (IOR
/// 1.5) or metal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Base colour per channel, in `[0, 1]` (glTF `baseColorFactor`; MTL
    /// `Kd`): a dielectric's diffuse albedo, a metal's Fresnel reflectance
    /// at normal incidence.
    pub albedo: Vec3,
    /// Emitted radiance (`Ke`; glTF `emissiveFactor` × emissive strength), `≥ 0`.
    pub emission: Vec3,
    /// Metallic factor in `[0, 1]` (glTF `metallicFactor`; MTL `Pm`).
    pub metallic: f32,
    /// Perceptual roughness in `[0, 1]` (glTF `roughnessFactor`; MTL `Pr`);
    /// GGX `α = roughness²` ([`slc_core::brdf::ggx_alpha`]).
    pub roughness: f32,
    /// The dielectric's Fresnel reflectance at normal incidence, per
    /// channel in `[0, 1]`: `((ior − 1)/(ior + 1))²` (0.04 at glTF's IOR
    /// 1.5), times `KHR_materials_specular`'s colour and factor.
    pub f0: Vec3,
    /// The dielectric's Fresnel reflectance at grazing incidence, in `[0,
    /// 1]`: 1, or `KHR_materials_specular`'s factor. With `f0 = 0` and
    /// `f90 = 0` the dielectric is Lambertian.
    pub f90: f32,
}

impl Material {
    /// A Lambertian material: diffuse albedo `albedo` (`f = albedo/π`), no
    /// specular lobe, emitting `emission`.
    pub fn lambertian(albedo: Vec3, emission: Vec3) -> Material {
        Material { albedo, emission, metallic: 0.0, roughness: 1.0, f0: Vec3::ZERO, f90: 0.0 }
    }

    /// glTF's metallic-roughness material without extensions: base colour
    /// `albedo`, `metallic`, perceptual `roughness`, a dielectric of IOR
    /// 1.5 (`f0 = 0.04`, `f90 = 1`), no emission.
    pub fn gltf(albedo: Vec3, metallic: f32, roughness: f32) -> Material {
        Material {
            albedo,
            emission: Vec3::ZERO,
            metallic,
            roughness,
            f0: Vec3::splat(0.04),
            f90: 1.0,
        }
    }

    /// GGX `α` ([`slc_core::brdf::ggx_alpha`] of the roughness).
    pub fn alpha(&self) -> f32 {
        slc_core::brdf::ggx_alpha(self.roughness)
    }

    /// `true` when the material has a specular lobe (not Lambertian).
    pub fn has_specular(&self) -> bool {
        slc_core::brdf::has_specular(self.metallic, self.f0, self.f90)
    }

    /// The BRDF `f(v, l)` at unit shading normal `n`
    /// ([`slc_core::brdf::brdf_eval`]).
    pub fn eval(&self, n: Vec3, v: Vec3, l: Vec3) -> Vec3 {
        slc_core::brdf::brdf_eval(
            self.albedo,
            self.metallic,
            self.f0,
            self.f90,
            self.alpha(),
            n,
            v,
            l,
        )
    }

    /// The lobes seen at `n·v` ([`slc_core::brdf::receiver_lobe`]).
    pub fn lobe(&self, n_v: f32) -> glam::Vec4 {
        slc_core::brdf::receiver_lobe(
            self.albedo,
            self.metallic,
            self.f0,
            self.f90,
            self.alpha(),
            n_v,
        )
    }

    /// The receiver at `p` with unit shading normal `n` seen from the unit
    /// direction `v` (toward the viewer), as light selection weighs it.
    pub fn receiver(&self, p: Vec3, n: Vec3, v: Vec3) -> Receiver {
        Receiver { p, n, r: slc_core::brdf::mirror_dir(n, v), lobe: self.lobe(n.dot(v)) }
    }

    /// Checks every field's range; `i` names the material in the error.
    pub fn validate(&self, i: usize) -> Result<(), SceneError> {
        let unit = |v: Vec3| v.is_finite() && v.min_element() >= 0.0 && v.max_element() <= 1.0;
        let unit1 = |x: f32| (0.0..=1.0).contains(&x);
        let bad = |what: String| Err(SceneError::Invalid(format!("material {i}: {what}")));
        if !unit(self.albedo) {
            return bad(format!("base colour (albedo) {:?} outside [0, 1]", self.albedo));
        }
        if !(self.emission.is_finite() && self.emission.min_element() >= 0.0) {
            return bad(format!("emission {:?} must be finite and >= 0", self.emission));
        }
        if !unit1(self.metallic) {
            return bad(format!("metallic {} outside [0, 1]", self.metallic));
        }
        if !unit1(self.roughness) {
            return bad(format!("roughness {} outside [0, 1]", self.roughness));
        }
        if !unit(self.f0) || !unit1(self.f90) {
            return bad(format!(
                "dielectric Fresnel f0 {:?}, f90 {} outside [0, 1]",
                self.f0, self.f90
            ));
        }
        Ok(())
    }
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

    /// Checks that position, target and up are finite, the first two
    /// distinct, up not along the view, and the vertical field of view in
    /// `(0°, 180°)`.
    pub fn validate(&self) -> Result<(), SceneError> {
        let fwd = self.target - self.position;
        if !(self.position.is_finite()
            && self.target.is_finite()
            && fwd.length() > 0.0
            && fwd.cross(self.up).length() > 0.0)
        {
            return Err(SceneError::Invalid(
                "camera: position, target and up must be finite, distinct and not parallel".into(),
            ));
        }
        if !(self.vfov_deg > 0.0 && self.vfov_deg < 180.0) {
            return Err(SceneError::Invalid(format!(
                "camera: vertical fov {} must be in (0, 180)",
                self.vfov_deg
            )));
        }
        Ok(())
    }

    /// The camera's view-projection for a `w × h` image with depth range
    /// `near..far` (right-handed view, wgpu clip space: depth in `[0, 1]`,
    /// y up): the matrix the GPU frame rasterizes with, whose pixel rays
    /// are [`Camera::ray_dir`]'s. The temporal stage reprojects with it.
    pub fn view_projection(&self, w: u32, h: u32, near: f32, far: f32) -> glam::Mat4 {
        use glam::camera::rh::{proj, view::look_to_mat4};
        let (_, up, forward) = self.basis();
        proj::directx::perspective(self.vfov_deg.to_radians(), w as f32 / h as f32, near, far)
            * look_to_mat4(self.position, forward, up)
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
            PrimaryLight::Spot { position, direction, intensity, inner, outer } => {
                SpotLight::new(position, direction, intensity, inner, outer).ok()
            }
            PrimaryLight::Directional { .. } => None,
        }
    }

    /// Unit direction from `x` toward this light (its light map's
    /// [`slc_core::frame::primary_light_dir`]): toward a spot's position,
    /// against a directional light's direction of travel.
    pub fn direction_from(&self, x: Vec3) -> Vec3 {
        use slc_core::frame::primary_light_dir;
        match *self {
            PrimaryLight::Spot { position, direction, .. } => {
                primary_light_dir(x, position, direction, true)
            }
            PrimaryLight::Directional { direction, .. } => {
                primary_light_dir(x, Vec3::ZERO, direction.normalize(), false)
            }
        }
    }

    /// Checks the light: a valid spot ([`SpotLight::new`]) with an outer
    /// angle below 85°, or a finite, non-zero direction with finite,
    /// non-negative irradiance.
    pub fn validate(&self) -> Result<(), SceneError> {
        match *self {
            PrimaryLight::Spot { position, direction, intensity, inner, outer } => {
                SpotLight::new(position, direction, intensity, inner, outer)
                    .map_err(|e| SceneError::Invalid(format!("primary spot light: {e}")))?;
                if outer >= 85f32.to_radians() {
                    return Err(SceneError::Invalid(
                        "primary spot outer angle must be below 85 degrees".into(),
                    ));
                }
            }
            PrimaryLight::Directional { direction, irradiance } => {
                if !(direction.is_finite()
                    && direction.length() > 0.0
                    && irradiance.is_finite()
                    && irradiance.min_element() >= 0.0)
                {
                    return Err(SceneError::Invalid(format!(
                        "primary directional light: direction {direction} must be finite and \
                         non-zero, irradiance {irradiance} finite and >= 0"
                    )));
                }
            }
        }
        Ok(())
    }

    /// The frame of this light's map in a scene with bounds `(lo, hi)`.
    pub fn light_map(&self, (lo, hi): (Vec3, Vec3)) -> LightMap {
        match *self {
            PrimaryLight::Spot { position, direction, outer, .. } => {
                let axis = direction.normalize();
                let (right, up) = LightMap::basis(axis);
                LightMap::Perspective { origin: position, axis, right, up, tan: outer.tan() }
            }
            PrimaryLight::Directional { direction, .. } => {
                let axis = direction.normalize();
                let (right, up) = LightMap::basis(axis);
                let half = 0.5 * (hi - lo).length();
                LightMap::Orthographic {
                    origin: (lo + hi) * 0.5 - axis * (2.0 * half),
                    axis,
                    right,
                    up,
                    half,
                }
            }
        }
    }
}

/// The frame of the primary light's map (the reflective shadow map and the
/// shadow map): texel `(tx, ty)` of a `size × size` map is the ray through
/// map coordinates `(a, b) = (light_map_coord(tx), light_map_coord(ty))`
/// ([`slc_core::frame::light_map_coord`]), row 0 toward `−up`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightMap {
    /// A spot's perspective map over its outer cone: rays from `origin`
    /// along `axis + right·a·tan + up·b·tan`.
    Perspective {
        /// The light's position.
        origin: Vec3,
        /// Unit axis.
        axis: Vec3,
        /// Unit right (`axis × helper`).
        right: Vec3,
        /// Unit up (`right × axis`).
        up: Vec3,
        /// `tan` of the outer half-angle.
        tan: f32,
    },
    /// A directional light's orthographic map over the scene's bounding
    /// sphere: rays along `axis` from `origin + right·a·half + up·b·half`,
    /// `origin` a diameter before the centre.
    Orthographic {
        /// Centre of the map's plane.
        origin: Vec3,
        /// Unit direction the light travels in.
        axis: Vec3,
        /// Unit right.
        right: Vec3,
        /// Unit up.
        up: Vec3,
        /// Half the map's edge (the bounding sphere's radius).
        half: f32,
    },
}

impl LightMap {
    /// `(right, up)` of a map looking along unit `axis`.
    fn basis(axis: Vec3) -> (Vec3, Vec3) {
        let helper = if axis.y.abs() < 0.9 { Vec3::Y } else { Vec3::X };
        let right = axis.cross(helper).normalize();
        (right, right.cross(axis))
    }

    /// Origin and unit direction of the ray of texel `(tx, ty)` of a
    /// `size × size` map, and what the texel gathers: the solid angle it
    /// covers (perspective) or its area (orthographic).
    pub fn texel_ray(&self, tx: u32, ty: u32, size: u32) -> (Vec3, Vec3, f32) {
        use slc_core::frame::{light_map_coord, rsm_texel_solid_angle};
        let (a, b) = (light_map_coord(tx, size), light_map_coord(ty, size));
        match *self {
            LightMap::Perspective { origin, axis, right, up, tan } => {
                let d = axis + right * (a * tan) + up * (b * tan);
                let dir = d.normalize();
                (
                    origin,
                    dir,
                    rsm_texel_solid_angle((2.0 * tan / size as f32).powi(2), dir.dot(axis)),
                )
            }
            LightMap::Orthographic { origin, axis, right, up, half } => (
                origin + right * (a * half) + up * (b * half),
                axis,
                (2.0 * half / size as f32).powi(2),
            ),
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
    /// Per-vertex unit shading normals, one triple per triangle, or empty
    /// (flat shading everywhere). Triangles of a mesh without normals carry
    /// their geometric normal three times. Shading uses the interpolated
    /// normal (`slc_core::ray::shading_normal`); ray offsets and the
    /// emitters' side use the geometric one.
    pub normals: Vec<[Vec3; 3]>,
    /// Material index per triangle.
    pub material_of: Vec<u32>,
    /// Materials.
    pub materials: Vec<Material>,
    /// Camera.
    pub camera: Camera,
    /// Primary light.
    pub primary: PrimaryLight,
    /// Material features the loader read but the renderer does not model
    /// (for the caller to report; the library does not print).
    pub unsupported: Vec<Unsupported>,
}

/// Material features of a loaded file that the renderer ignores (it models
/// the metallic-roughness factors and emission: no textures, transparency
/// or refraction), by material.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Unsupported {
    /// Where the material comes from (the OBJ's name).
    pub source: String,
    /// Material name.
    pub material: String,
    /// Keys that are ignored (`map_Kd`, `d`, `Ni`, glTF's `baseColorTexture`, ...).
    pub features: Vec<String>,
}

impl Unsupported {
    /// One line for a user: `"bunny.obj: material 'glass' has d, map_Kd (ignored: slc renders the material's factors, no textures, transparency or refraction)"`.
    pub fn message(&self) -> String {
        format!(
            "{}: material '{}' has {} (ignored: slc renders the material's factors, no textures, transparency or refraction)",
            self.source,
            self.material,
            self.features.join(", ")
        )
    }
}

impl Scene {
    /// Checks the invariants every renderer relies on: those of
    /// [`Scene::validate_surfaces`] and a usable primary light (the VPL
    /// application's).
    pub fn validate(&self) -> Result<(), SceneError> {
        self.validate_surfaces()?;
        self.primary.validate()
    }

    /// Checks what the path tracers rely on, which light the scene with its
    /// emitters and given lights and never read the primary light: finite
    /// vertices, valid material indices, valid materials
    /// ([`Material::validate`]), finite unit vertex normals, a usable camera.
    pub fn validate_surfaces(&self) -> Result<(), SceneError> {
        if self.triangles.is_empty() {
            return Err(SceneError::Empty);
        }
        if self.material_of.len() != self.triangles.len() {
            return Err(SceneError::Invalid("one material index per triangle".into()));
        }
        if !self.normals.is_empty() && self.normals.len() != self.triangles.len() {
            return Err(SceneError::Invalid(format!(
                "{} normal triples for {} triangles",
                self.normals.len(),
                self.triangles.len()
            )));
        }
        for (i, ns) in self.normals.iter().enumerate() {
            if !ns.iter().all(|n| n.is_finite() && (n.length() - 1.0).abs() < 1e-3) {
                return Err(SceneError::Invalid(format!(
                    "triangle {i}: vertex normals {ns:?} must be finite unit vectors"
                )));
            }
        }
        for (i, t) in self.triangles.iter().enumerate() {
            if !t.iter().all(|v| v.is_finite()) {
                return Err(SceneError::NonFiniteVertex(i));
            }
            if self.material_of[i] as usize >= self.materials.len() {
                return Err(SceneError::Invalid(format!(
                    "triangle {i} names material {} of {}",
                    self.material_of[i],
                    self.materials.len()
                )));
            }
        }
        for (i, m) in self.materials.iter().enumerate() {
            m.validate(i)?;
        }
        // Nothing to see or to bound: a camera framed on it would sit at its
        // one point, and a render would be black.
        if self.triangles.iter().all(|t| (t[1] - t[0]).cross(t[2] - t[0]) == Vec3::ZERO) {
            return Err(SceneError::Invalid(format!(
                "all {} triangles have zero area (repeated or collinear vertices)",
                self.triangles.len()
            )));
        }
        self.camera.validate()
    }

    /// `true` when some triangle has vertex normals that differ from its
    /// geometric normal (smooth shading somewhere).
    pub fn has_vertex_normals(&self) -> bool {
        !self.normals.is_empty()
    }

    /// Unit geometric normal of triangle `i` from its winding (zero for a
    /// degenerate triangle).
    pub fn geometric_normal(&self, i: usize) -> Vec3 {
        let [a, b, c] = self.triangles[i];
        slc_core::ray::triangle_normal(a, b, c)
    }

    /// The three vertex normals of triangle `i` (its geometric normal three
    /// times when the scene has none).
    pub fn vertex_normals(&self, i: usize) -> [Vec3; 3] {
        match self.normals.get(i) {
            Some(n) => *n,
            None => [self.geometric_normal(i); 3],
        }
    }

    /// Shading normal at point `p` on triangle `i`, on the side of `facing`
    /// (the geometric normal oriented toward the viewer): the interpolated
    /// vertex normal ([`slc_core::ray::shading_normal`], written once with
    /// the GPU's), or `facing` itself for flat triangles.
    pub fn shading_normal(&self, i: usize, p: Vec3, facing: Vec3) -> Vec3 {
        match self.normals.get(i) {
            Some([n0, n1, n2]) => {
                let [a, b, c] = self.triangles[i];
                slc_core::ray::shading_normal(
                    *n0,
                    *n1,
                    *n2,
                    slc_core::ray::barycentric(p, a, b, c),
                    facing,
                )
            }
            None => facing,
        }
    }

    /// Appends `other` scaled by `scale` (> 0) and moved by `translate`;
    /// materials are appended and re-indexed, and vertex normals are kept
    /// (geometric ones fill in for the side that has none).
    pub fn append(&mut self, other: Scene, scale: f32, translate: Vec3) {
        if self.normals.is_empty() && !other.normals.is_empty() {
            self.normals = (0..self.triangles.len()).map(|i| self.vertex_normals(i)).collect();
        }
        if !self.normals.is_empty() {
            self.normals.extend((0..other.triangles.len()).map(|i| other.vertex_normals(i)));
        }
        let base = self.materials.len() as u32;
        self.materials.extend(other.materials);
        self.triangles.extend(other.triangles.iter().map(|t| t.map(|v| v * scale + translate)));
        self.material_of.extend(other.material_of.iter().map(|m| m + base));
        self.unsupported.extend(other.unsupported);
    }

    /// Axis-aligned bounds of all vertices.
    pub fn bounds(&self) -> (Vec3, Vec3) {
        self.triangles
            .iter()
            .flatten()
            .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)))
    }

    /// Length of the bounds' diagonal.
    pub fn diagonal(&self) -> f32 {
        let (lo, hi) = self.bounds();
        (hi - lo).length()
    }

    /// Sets the default camera and primary light for a loaded scene (see
    /// [`Scene::load_obj`]).
    pub fn frame_default_view(&mut self) {
        let (lo, hi) = self.bounds();
        let c = (lo + hi) * 0.5;
        let ext = hi - lo;
        let vfov: f32 = 39.3;
        let dist = 0.5 * ext.y.max(ext.x) / (vfov.to_radians() * 0.5).tan();
        self.camera = Camera {
            position: Vec3::new(c.x, c.y, hi.z + dist * 1.02),
            target: c,
            up: Vec3::Y,
            vfov_deg: vfov,
        };
        // Emitters: area-weighted centroid, mean normal, I₀ = Σ L·A.
        let (mut area_sum, mut centroid, mut normal, mut power) =
            (0.0f32, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
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
