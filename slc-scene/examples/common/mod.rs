//! What the BSH walk examples (`walk_visits`, `wide_walk`) share: a scene
//! set up for the path tracers at the automatic ε, one ξ set's squared
//! ranges (seed 1, pass 0), and the shading points they walk from.
#![allow(dead_code)] // Each example uses its part.

use glam::Vec3;
use slc_core::range::{RangeParams, random_range2};
use slc_core::xi::xi_for;
use slc_scene::error_bound::{TARGET_CANDIDATES, auto_error_bound};
use slc_scene::placement::{Stream, Surfaces};
use slc_scene::pt::PtScene;
use slc_scene::scene_file::SceneFile;

/// A scene file's path-tracing scene and one pass's ranges.
pub struct Walked {
    /// The file's stem.
    pub name: String,
    pub pts: PtScene,
    /// The automatic ε.
    pub eps: f32,
    /// Each light's squared random range for ξ set (seed 1, pass 0).
    pub r2: Vec<f32>,
}

impl Walked {
    pub fn load(path: &str) -> Result<Walked, Box<dyn std::error::Error>> {
        let f = SceneFile::load(std::path::Path::new(path))?;
        let pts = PtScene::new(&f.scene, &f.lights)?;
        let eps = auto_error_bound(&pts, 1.0, TARGET_CANDIDATES).ok_or("no automatic bound")?;
        let params = RangeParams::new(eps, 1.0)?;
        let r2 = pts
            .lights()
            .iter()
            .enumerate()
            .map(|(i, l)| random_range2(params.threshold_range2(l.peak()), xi_for(1, 0, i as u32)))
            .collect();
        let name = std::path::Path::new(path)
            .file_stem()
            .map_or(path.to_string(), |s| s.to_string_lossy().into());
        Ok(Walked { name, pts, eps, r2 })
    }

    /// `n` shading points, uniform by area on the non-emissive surfaces.
    pub fn points(&self, n: u32) -> Result<Vec<Vec3>, Box<dyn std::error::Error>> {
        Ok(self.points_with_normals(n)?.into_iter().map(|(x, _)| x).collect())
    }

    /// [`Self::points`] with each one's surface normal.
    pub fn points_with_normals(
        &self,
        n: u32,
    ) -> Result<Vec<(Vec3, Vec3)>, Box<dyn std::error::Error>> {
        let surfaces = Surfaces::new(self.pts.scene())?;
        Ok((0..n).map(|k| surfaces.sample(&mut Stream::new(0x1234, k))).collect())
    }
}
