//! # slc-scene
//!
//! What both slc backends take and return, so that neither is the other's
//! front end (std; no rayon, no wgpu):
//!
//! | module | holds |
//! |---|---|
//! | [`scene`] | the scene model: triangles with optional vertex normals, materials, camera, primary light, validation |
//! | [`cornell`], `obj`, `gltf`, `scene_file` | the built-in Cornell box; OBJ+MTL through tobj, glTF 2.0 (`.gltf`/`.glb`) through the gltf crate and TOML scene files (feature `io`, on by default) |
//! | [`shapes`] | built-in shapes (the unit sphere, midpoint subdivision; no I/O, so not behind `io`) |
//! | [`placement`] | seeded placement on a scene's surfaces, the same on every machine |
//! | `light_cloud` | a scene file's `[[light_cloud]]`: many seeded punctual lights (feature `io`) |
//! | [`error_bound`] | the path tracer's ε set from the scene itself |
//! | [`lights`] | a light set with its BSH and power alias table; emissive triangles → triangle lights |
//! | [`occluders`] | what shadow rays hit: meshes and their instances as one world-space BVH, refitted where instances move |
//! | [`light_bvh`] | the light BVH of the `lightbvh` baseline (built here, sampled by slc-core on both backends) |
//! | [`alias`] | Walker's alias table (the `power` baseline) |
//! | [`image`] | linear HDR images, RMSE; EXR/PNG I/O (feature `io`) |
//! | [`culling`] | how lights are culled ([`culling::Culling`], its parameters inside each variant), the one vocabulary of the CPU frame, the GPU passes, the CLI and slc-bevy |
//! | [`vpl`] | application A's settings, G-buffer, VPLs, shaded irradiance and frame |
//! | [`pt`] | application B's settings, method enum, prepared scene and accumulation |
//! | [`temporal`] | each frame's camera and the settings of the temporal stage |
//! | [`backend`] | the contract both backends implement, one trait per application |
//!
//! ```
//! use slc_scene::pt::PtScene;
//! use slc_scene::scene::Scene;
//!
//! let pts = PtScene::new(&Scene::cornell_box(), &[]).unwrap();
//! assert_eq!(pts.light_count(), 2); // the ceiling light's two triangles
//! ```
#![forbid(unsafe_code)]
#![deny(missing_docs)]
// `!(x > 0.0)` is how the validators reject NaN along with the bad range.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod alias;
pub mod backend;
pub mod cornell;
pub mod culling;
pub mod error_bound;
#[cfg(feature = "io")]
pub mod gltf;
pub mod image;
pub mod light_bvh;
#[cfg(feature = "io")]
pub mod light_cloud;
pub mod lights;
#[cfg(feature = "io")]
pub mod obj;
pub mod occluders;
pub mod placement;
pub mod pt;
pub mod scene;
#[cfg(feature = "io")]
pub mod scene_file;
pub mod shapes;
pub mod stats;
pub mod temporal;
pub mod vpl;

use thiserror::Error;

/// A scene that cannot be loaded or used.
#[derive(Debug, Error, PartialEq)]
pub enum SceneError {
    /// The file could not be read.
    #[error("cannot read {0}: {1}")]
    Io(String, String),
    /// The OBJ/MTL could not be parsed.
    #[error("invalid OBJ/MTL {0}: {1}")]
    Obj(String, String),
    /// The glTF file could not be parsed or holds a bad value.
    #[error("invalid glTF {0}: {1}")]
    Gltf(String, String),
    /// No triangles.
    #[error("the scene has no triangles")]
    Empty,
    /// A vertex with NaN or ±∞.
    #[error("triangle {0} has a non-finite vertex")]
    NonFiniteVertex(usize),
    /// Another invalid value.
    #[error("invalid scene: {0}")]
    Invalid(String),
    /// A scene file that does not parse or holds a bad value.
    #[error("scene file {0}: {1}")]
    File(String, String),
}

impl SceneError {
    /// The error with the file it came from named: a scene error that does
    /// not name one (no triangles, a bad vertex, an invalid value) becomes
    /// [`SceneError::File`] of `path`; the others already name theirs.
    pub fn in_file(self, path: &std::path::Path) -> SceneError {
        match self {
            SceneError::Empty | SceneError::NonFiniteVertex(_) | SceneError::Invalid(_) => {
                SceneError::File(path.display().to_string(), self.to_string())
            }
            named => named,
        }
    }
}

/// Invalid render settings.
#[derive(Debug, Error, PartialEq)]
pub enum RenderError {
    /// Scene problem.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// Image size out of range.
    #[error("image size {0}x{1} must be within 1..={MAX_IMAGE_SIDE} on each side")]
    Size(u32, u32),
    /// VPL count that is not the square of a multiple of 8.
    #[error(
        "{0} VPLs: the count must be s*s for s a multiple of 8 up to 4096 (e.g. 4096, 16384, 65536, 262144)"
    )]
    VplCount(u64),
    /// Another bad setting.
    #[error("invalid setting: {0}")]
    Setting(String),
}

/// An image that could not be written or read.
#[derive(Debug, Error, PartialEq)]
#[error("cannot write or read image {0}: {1}")]
pub struct OutputError(pub String, pub String);

/// Checks an exposure (the scale before tone mapping, and the SLC error
/// bound's reference brightness): finite and positive.
pub fn check_exposure(exposure: f32) -> Result<(), RenderError> {
    if exposure.is_finite() && exposure > 0.0 {
        Ok(())
    } else {
        Err(RenderError::Setting(format!("exposure {exposure} must be finite and positive")))
    }
}

/// The largest image side any renderer takes.
pub const MAX_IMAGE_SIDE: u32 = 16384;

/// Checks an image size: `1..=`[`MAX_IMAGE_SIDE`] on each side.
pub fn check_size(width: u32, height: u32) -> Result<(), RenderError> {
    if (1..=MAX_IMAGE_SIDE).contains(&width) && (1..=MAX_IMAGE_SIDE).contains(&height) {
        Ok(())
    } else {
        Err(RenderError::Size(width, height))
    }
}
