//! What the render world takes from the main world every frame: the lights
//! slc shades (point and spot lights with [`SlcLight`], emissive meshes'
//! triangles) in Bevy's units, and the shadow casters as slc's
//! [`Occluders`].

use crate::emissive;
use crate::{NotSlcLight, SlcLight};
use bevy::light::NotShadowCaster;
use bevy::mesh::UvChannel;
use bevy::prelude::*;
use bevy::render::Extract;
use slc_wgpu::{
    Instance, Light, Occluders, PointLight as SlcPoint, SpotLight as SlcSpot, TriangleLight,
};
use std::collections::HashMap;

/// The lights slc shades this frame, in Bevy's terms: RGB luminous
/// intensity in candela (Bevy's lumens / 4π, for spots too, as Bevy does),
/// before the camera's exposure.
#[derive(Resource, Default)]
pub(crate) struct ExtractedLights(pub(crate) Vec<BevyLight>);

#[derive(Clone, Copy, Debug)]
pub(crate) enum BevyLight {
    Point {
        position: glam::Vec3,
        candela: glam::Vec3,
    },
    /// Bevy's spot: axis the transform's forward (−Z); the cone angles as
    /// Bevy's extraction clamps them (outer below π/2, inner at most outer).
    Spot {
        position: glam::Vec3,
        axis: glam::Vec3,
        candela: glam::Vec3,
        inner: f32,
        outer: f32,
    },
    /// A triangle of an emissive mesh in world space, counter-clockwise
    /// from its emitting side (Bevy's front face), and its radiance in
    /// cd/m² (the material's `emissive`).
    Triangle {
        vertices: [glam::Vec3; 3],
        nits: glam::Vec3,
    },
}

fn candela(color: Color, lumens: f32) -> glam::Vec3 {
    let c = LinearRgba::from(color);
    glam::Vec3::new(c.red, c.green, c.blue) * (lumens / (4.0 * std::f32::consts::PI))
}

fn to_vec3(v: Vec3) -> glam::Vec3 {
    glam::Vec3::new(v.x, v.y, v.z)
}

/// What [`extract_lights`] reads of an emissive mesh.
type EmitterItem = (
    &'static Mesh3d,
    &'static MeshMaterial3d<StandardMaterial>,
    &'static GlobalTransform,
    &'static InheritedVisibility,
);

/// Each emissive mesh asset's triangles in object space (or why it
/// lights nothing), read once and kept until the asset changes.
type EmitterCache = HashMap<AssetId<Mesh>, Result<Vec<[glam::Vec3; 3]>, String>>;

/// Each textured emitter's per-triangle texture means
/// ([`emissive::triangle_means`]) by mesh, image, UV channel and
/// `uv_transform` (its bits), kept until the mesh or image changes.
type TextureCache =
    HashMap<(AssetId<Mesh>, AssetId<Image>, bool, [u32; 6]), Result<Vec<glam::Vec3>, String>>;

#[allow(clippy::too_many_arguments)] // A system's parameters.
pub(crate) fn extract_lights(
    mut out: ResMut<ExtractedLights>,
    mut cache: Local<EmitterCache>,
    mut textured: Local<TextureCache>,
    points: Extract<Query<(&PointLight, &GlobalTransform), With<SlcLight>>>,
    spots: Extract<Query<(&SpotLight, &GlobalTransform), With<SlcLight>>>,
    emitters: Extract<Query<EmitterItem, Without<NotSlcLight>>>,
    meshes: Extract<Res<Assets<Mesh>>>,
    images: Extract<Res<Assets<Image>>>,
    materials: Extract<Res<Assets<StandardMaterial>>>,
    mut events: Extract<MessageReader<AssetEvent<Mesh>>>,
    mut image_events: Extract<MessageReader<AssetEvent<Image>>>,
) {
    out.0.clear();
    for e in events.read() {
        if let AssetEvent::Modified { id } | AssetEvent::Removed { id } = e {
            cache.remove(id);
            textured.retain(|k, _| k.0 != *id);
        }
    }
    for e in image_events.read() {
        if let AssetEvent::Modified { id } | AssetEvent::Removed { id } = e {
            textured.retain(|k, _| k.1 != *id);
        }
    }
    let mut emitting = 0;
    for (mesh, material, transform, visible) in &emitters {
        let Some(m) = materials.get(material.id()) else { continue };
        let e = m.emissive;
        let nits = glam::Vec3::new(e.red, e.green, e.blue);
        if !visible.get() || nits.max_element() <= 0.0 {
            continue;
        }
        emitting += 1;
        let tris = match cache.get(&mesh.id()) {
            Some(t) => t,
            None => {
                // Not loaded yet: looked at again next frame.
                let Some(asset) = meshes.get(mesh.id()) else { continue };
                cache.entry(mesh.id()).or_insert(mesh_triangles(asset))
            }
        };
        let tris = match tris {
            Ok(t) => t,
            Err(e) => {
                warn_once!("slc: an emissive mesh lights nothing: {e}");
                continue;
            }
        };
        // A textured emitter: each triangle's texture mean, read once per
        // mesh, image and mapping (not loaded yet: next frame).
        let means = match &m.emissive_texture {
            None => None,
            Some(texture) => {
                let uv = m.uv_transform.to_cols_array().map(f32::to_bits);
                let key = (mesh.id(), texture.id(), m.emissive_channel == UvChannel::Uv1, uv);
                use std::collections::hash_map::Entry;
                let means = match textured.entry(key) {
                    Entry::Occupied(kept) => kept.into_mut(),
                    Entry::Vacant(slot) => {
                        let (Some(asset), Some(image)) =
                            (meshes.get(mesh.id()), images.get(texture))
                        else {
                            continue;
                        };
                        slot.insert(emissive::triangle_means(
                            asset,
                            image,
                            m.emissive_channel.clone(),
                            m.uv_transform,
                        ))
                    }
                };
                match &*means {
                    Ok(means) if means.len() == tris.len() => Some(means),
                    Ok(_) => {
                        warn_once!(
                            "slc: an emissive mesh's texture means do not match its triangles: its texture is not applied"
                        );
                        None
                    }
                    Err(e) => {
                        warn_once!("slc: {e}: the emissive mesh lights without its texture");
                        None
                    }
                }
            }
        };
        let a = glam::Affine3A::from_cols_array(&transform.affine().to_cols_array());
        for (i, t) in tris.iter().enumerate() {
            let nits = means.map_or(nits, |m| nits * m[i]);
            // A black part of the texture lights nothing: no light.
            if nits.max_element() <= 0.0 {
                continue;
            }
            let v = t.map(|p| a.transform_point3(p));
            out.0.push(BevyLight::Triangle { vertices: v, nits });
            if m.double_sided {
                out.0.push(BevyLight::Triangle { vertices: [v[0], v[2], v[1]], nits });
            }
        }
    }
    // Meshes made and dropped as the app runs: read again when most of
    // the cache is no longer in use.
    if cache.len() > 64 + 2 * emitting {
        cache.clear();
    }
    if textured.len() > 64 + 2 * emitting {
        textured.clear();
    }
    for (light, transform) in &points {
        out.0.push(BevyLight::Point {
            position: to_vec3(transform.translation()),
            candela: candela(light.color, light.intensity),
        });
    }
    for (light, transform) in &spots {
        let outer = light.outer_angle.min(std::f32::consts::FRAC_PI_2 - 1e-4);
        out.0.push(BevyLight::Spot {
            position: to_vec3(transform.translation()),
            axis: to_vec3(*transform.forward()),
            candela: candela(light.color, light.intensity),
            inner: light.inner_angle.clamp(0.0, outer.max(0.0)),
            outer: outer.max(0.0),
        });
    }
}

/// The scene's meshes as slc's occluders (render world).
#[derive(Resource, Default)]
pub(crate) struct ExtractedOccluders {
    pub(crate) occluders: Occluders,
    /// Each mesh asset's mesh in `occluders`, or `None` where it cannot
    /// occlude (warned once).
    mesh_of: HashMap<AssetId<Mesh>, Option<u32>>,
    /// The instances by entity, in order: a changed list is laid out anew.
    entities: Vec<(Entity, u32)>,
    /// Bumped whenever the occluders change.
    pub(crate) generation: u64,
    /// Why the occluders cannot be used (shadows are off until it clears).
    pub(crate) error: Option<String>,
}

/// A mesh asset's triangles in object space, or why it cannot occlude.
pub(crate) fn mesh_triangles(mesh: &Mesh) -> Result<Vec<[glam::Vec3; 3]>, String> {
    Ok(mesh.triangles().map_err(|e| e.to_string())?.map(|t| t.vertices.map(to_vec3)).collect())
}

/// What [`extract_occluders`] reads of a shadow caster.
type CasterItem = (Entity, &'static Mesh3d, &'static GlobalTransform, &'static InheritedVisibility);

/// Reads the shadow casters: new mesh assets get their BVH, moved
/// entities are refitted, a changed set of entities is laid out anew.
pub(crate) fn extract_occluders(
    mut out: ResMut<ExtractedOccluders>,
    meshes: Extract<Res<Assets<Mesh>>>,
    mut events: Extract<MessageReader<AssetEvent<Mesh>>>,
    casters: Extract<Query<CasterItem, Without<NotShadowCaster>>>,
) {
    let out = &mut *out;
    // Start over (every used mesh's BVH built again) when a mesh asset in
    // use was edited, or when most of the meshes built are no longer used
    // (assets made and dropped as the app runs).
    let edited = events
        .read()
        .any(|e| matches!(e, AssetEvent::Modified { id } if out.mesh_of.contains_key(id)));
    let used: std::collections::HashSet<u32> = out.entities.iter().map(|e| e.1).collect();
    if edited || out.occluders.mesh_count() > 64 + 2 * used.len() {
        out.occluders = Occluders::default();
        out.mesh_of.clear();
        out.entities.clear();
    }
    let (mut entities, mut transforms) = (Vec::new(), Vec::new());
    for (entity, mesh, transform, visible) in &casters {
        if !visible.get() {
            continue;
        }
        let id = mesh.id();
        let index = match out.mesh_of.get(&id) {
            Some(&i) => i,
            // Not loaded yet: looked at again next frame.
            None if meshes.get(id).is_none() => continue,
            None => {
                let i = meshes
                    .get(id)
                    .map_or(Err("not loaded".into()), mesh_triangles)
                    .and_then(|t| out.occluders.add_mesh(&t).map_err(|e| e.to_string()))
                    .map_err(|e| warn!("slc: mesh {id:?} casts no slc shadow: {e}"))
                    .ok();
                out.mesh_of.insert(id, i);
                i
            }
        };
        let t = glam::Affine3A::from_cols_array(&transform.affine().to_cols_array());
        if let Some(i) = index
            && slc_wgpu::occluders::placeable(&t)
        {
            entities.push((entity, i));
            transforms.push(t);
        }
    }
    let result = if entities == out.entities {
        out.occluders.set_transforms(&transforms).map(|moved| moved.then_some(()))
    } else {
        let instances: Vec<Instance> = entities
            .iter()
            .zip(&transforms)
            .map(|(&(_, mesh), &transform)| Instance { mesh, transform })
            .collect();
        out.entities = entities;
        out.occluders.set_instances(&instances).map(Some)
    };
    match result {
        Ok(None) => {}
        Ok(Some(())) => {
            out.generation += 1;
            out.error = None;
        }
        Err(e) => {
            if out.error.is_none() {
                warn!("slc: shadows are off: {e}");
            }
            out.error = Some(e.to_string());
            out.generation += 1;
        }
    }
}

/// The view's lights in slc's form: candela times the camera's exposure.
/// A light slc cannot shade (NaN, infinite or negative intensity, a NaN
/// position or angle) is left out, with one warning in the log for the
/// first such light.
pub(crate) fn slc_lights(lights: &[BevyLight], exposure: f32) -> Vec<Light> {
    lights
        .iter()
        .filter_map(|l| {
            match *l {
                BevyLight::Point { position, candela } => {
                    SlcPoint::new(position, candela * exposure)
                        .map(Light::Point)
                        .map_err(|e| format!("point light at {position}: {e}"))
                }
                // Bevy's spot fall-off is the quadratic one.
                BevyLight::Spot { position, axis, candela, inner, outer } => {
                    SlcSpot::new(position, axis, candela * exposure, inner, outer)
                        .map(|s| Light::Spot(s.with_quadratic_falloff()))
                        .map_err(|e| format!("spot light at {position}: {e}"))
                }
                BevyLight::Triangle { vertices: [a, b, c], nits } => {
                    TriangleLight::new(a, b, c, nits * exposure)
                        .map(Light::Triangle)
                        .map_err(|e| format!("emissive triangle at {a}: {e}"))
                }
            }
            .map_err(|e| {
                warn_once!("slc: a light is left out (and any other it cannot shade): {e}")
            })
            .ok()
        })
        .collect()
}
