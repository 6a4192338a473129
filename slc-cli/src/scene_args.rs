//! Scene and image options shared by `render` and `bench`, and loading
//! them (built-in, OBJ or scene file), with the loader's warnings printed.

use crate::backends::Backend;
use clap::{Args, ValueEnum};
use slc_cpu::vpl::VplContext;
use slc_scene::gltf::GltfScene;
use slc_scene::scene::Scene;
use slc_scene::scene_file::{RenderSettings, SceneFile};
use slc_scene::vpl::VplSettings;
use std::path::Path;

/// `--shadow-size`'s default: the edge of the GPU frame's shadow map.
pub const DEFAULT_SHADOW_SIZE: u32 = 2048;

/// Which application of the paper.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum App {
    /// Real-time indirect illumination with VPLs.
    Vpl,
    /// Progressive path tracing with many lights.
    Pt,
}

/// Whether the path tracers look up each pass's grids over the light
/// hierarchy (`--grid`).
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum Grid {
    /// Look in the grids.
    On,
    /// Walk the hierarchy at every vertex.
    Off,
}

/// Scene and image options shared by render and bench. Values resolve as:
/// command-line flag, else the scene file's `[render]`, else the default.
#[derive(Args, Clone, Debug)]
pub struct SceneArgs {
    /// Application.
    #[arg(long, value_enum, default_value = "vpl")]
    pub app: App,
    /// Backend.
    #[arg(long, value_enum, default_value = "cpu")]
    pub backend: Backend,
    /// `cornell` or `cornell-glossy` (built in), an OBJ file (with its MTL), a glTF 2.0 file (`.gltf`, `.glb`), or a TOML scene file.
    #[arg(long, default_value = "cornell")]
    pub scene: String,
    /// Image width [default: 512; 128 for `bench --app pt`].
    #[arg(long)]
    pub width: Option<u32>,
    /// Image height [default: 512; 128 for `bench --app pt`].
    #[arg(long)]
    pub height: Option<u32>,
    /// Number of VPLs: s·s with s a multiple of 8 (4096, 16384, 65536, 262144) [default: 65536].
    #[arg(long)]
    pub vpls: Option<u64>,
    /// Exposure E, used by the error bound and the PNG preview [default: 1].
    #[arg(long)]
    pub exposure: Option<f32>,
    /// Clamp distance of the VPL fall-off (default: 1% of the scene diagonal).
    #[arg(long)]
    pub min_distance: Option<f32>,
    /// Near-field radius: each pixel shades the VPLs this close itself, not interleaved, which removes the 8×8 blotches at creases; 0 turns the split off [default: 3 × the min distance, 0.0285 in the built-in box].
    #[arg(long)]
    pub near_radius: Option<f32>,
    /// Culling tile size in sub-image pixels (CPU backend) [default: 4].
    #[arg(long)]
    pub tile: Option<u32>,
    /// Edge of the primary light's shadow map (GPU frame; the CPU casts shadow rays) [default: 2048].
    #[arg(long)]
    pub shadow_size: Option<u32>,
    /// GPU path tracer: cast the light connections' shadow rays as the adapter's ray queries (wgpu's experimental ray queries: GPUs with ray tracing, Mesa 25's lavapipe) instead of the WGSL BVH walk; the closest hits still walk it.
    #[arg(long)]
    pub ray_query: bool,
    /// Path tracers: find a vertex's lights in each pass's grids over the light hierarchy, or walk it at every vertex (the same lights in the same order, so the same image) [default: on for the CPU; off for the GPU, where lavapipe measured it slower and a real GPU has not measured it yet].
    #[arg(long, value_enum)]
    pub grid: Option<Grid>,
}

/// The resolved scene and sizes of the VPL application.
pub struct Resolved {
    /// The scene.
    pub scene: Scene,
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// RSM edge (`rsm_size²` VPLs).
    pub rsm_size: u32,
    /// Exposure.
    pub exposure: f32,
    /// The scene file's `[render]` (empty for built-in and OBJ scenes).
    pub file: RenderSettings,
}

/// A scene ready to render, with its resolved settings.
pub struct Loaded {
    /// Shared buffers of the VPL application.
    pub ctx: VplContext,
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// Exposure.
    pub exposure: f32,
    /// The scene file's `[render]` (empty for built-in and OBJ scenes).
    pub file: RenderSettings,
}

impl SceneArgs {
    /// The scene, its extra lights (scene files) and its `[render]` settings.
    /// Material features the renderer ignores get one warning line per
    /// material on stderr.
    pub fn scene(&self) -> anyhow::Result<(Scene, Vec<slc_core::light::Light>, RenderSettings)> {
        let path = Path::new(&self.scene);
        let loaded = if self.scene == "cornell" {
            (Scene::cornell_box(), Vec::new(), RenderSettings::default())
        } else if self.scene == "cornell-glossy" {
            (Scene::cornell_box_glossy(), Vec::new(), RenderSettings::default())
        } else if self.scene.ends_with(".toml") {
            let f = SceneFile::load(path)?;
            (f.scene, f.lights, f.render)
        } else if self.scene.ends_with(".gltf") || self.scene.ends_with(".glb") {
            let g = GltfScene::load(path).map_err(|e| e.in_file(path))?;
            (g.scene, g.lights, RenderSettings::default())
        } else {
            let s = Scene::load_obj(path).map_err(|e| e.in_file(path))?;
            (s, Vec::new(), RenderSettings::default())
        };
        let mut said = Vec::new();
        for u in &loaded.0.unsupported {
            let line = u.message();
            if !said.contains(&line) {
                eprintln!("warning: {line}");
                said.push(line);
            }
        }
        Ok(loaded)
    }

    /// `--grid` as the path tracers take it (`None`: the backend's default).
    pub fn grid_on(&self) -> Option<bool> {
        self.grid.map(|g| g == Grid::On)
    }

    /// Refuses the path tracer's flags for the VPL application.
    pub fn pt_only_flags(&self) -> anyhow::Result<()> {
        if self.ray_query {
            anyhow::bail!(
                "--ray-query: only the GPU path tracer (--app pt --backend gpu) casts ray queries"
            );
        }
        if self.grid.is_some() {
            anyhow::bail!("--grid: only the path tracers (--app pt) build grids");
        }
        Ok(())
    }

    /// Refuses the VPL frame's flags for the backend that would ignore
    /// them: `--tile` sizes the CPU's culling tiles (the GPU's are its
    /// workgroups), `--shadow-size` the GPU frame's shadow map (the CPU
    /// casts shadow rays).
    pub fn backend_flags(&self) -> anyhow::Result<()> {
        match self.backend {
            Backend::Gpu if self.tile.is_some() => {
                anyhow::bail!(
                    "--tile: only the CPU frame (--backend cpu) culls in tiles of that size"
                )
            }
            Backend::Cpu if self.shadow_size.is_some() => anyhow::bail!(
                "--shadow-size: only the GPU frame (--backend gpu) renders a shadow map; the CPU casts shadow rays"
            ),
            _ => Ok(()),
        }
    }

    /// Refuses the VPL application's flags for the path tracers, which
    /// would ignore them (a scene file's `[render]` values for the other
    /// application are not flags: they stay allowed).
    pub fn vpl_only_flags(&self) -> anyhow::Result<()> {
        let given = [
            ("--vpls", self.vpls.is_some()),
            ("--min-distance", self.min_distance.is_some()),
            ("--near-radius", self.near_radius.is_some()),
            ("--tile", self.tile.is_some()),
            ("--shadow-size", self.shadow_size.is_some()),
        ];
        match given.iter().find(|(_, on)| *on) {
            Some((flag, _)) => {
                anyhow::bail!("{flag}: only the VPL application (--app vpl) takes it")
            }
            None => Ok(()),
        }
    }

    /// `--tile`, else the default tile size.
    pub fn tile(&self) -> u32 {
        self.tile.unwrap_or(VplSettings::default().tile)
    }

    /// The exposure (`--exposure`, else the scene file's, else 1), checked
    /// for every method and application (an exposure of 0 or NaN made a
    /// black image wherever SLC's error bound did not use it).
    pub fn exposure_of(&self, file: &RenderSettings) -> anyhow::Result<f32> {
        let exposure = self.exposure.or(file.exposure).unwrap_or(1.0);
        slc_scene::check_exposure(exposure)?;
        Ok(exposure)
    }

    /// Loads the scene and resolves the VPL application's sizes.
    pub fn resolve(&self) -> anyhow::Result<Resolved> {
        let (scene, _, file) = self.scene()?;
        let width = self.width.or(file.width).unwrap_or(512);
        let height = self.height.or(file.height).unwrap_or(512);
        let vpls = self.vpls.or(file.vpls).unwrap_or(65536);
        slc_scene::check_size(width, height)?;
        let exposure = self.exposure_of(&file)?;
        let rsm_size = slc_scene::vpl::rsm_side(vpls)?;
        Ok(Resolved { scene, width, height, rsm_size, exposure, file })
    }

    /// Loads the scene and builds the CPU's shared VPL context.
    pub fn load(&self) -> anyhow::Result<Loaded> {
        let r = self.resolve()?;
        let ctx = VplContext::new(&r.scene, r.width, r.height, r.rsm_size, self.min_distance)?;
        Ok(Loaded { ctx, width: r.width, height: r.height, exposure: r.exposure, file: r.file })
    }

    /// The whole-GPU VPL frame of the resolved scene.
    pub fn gpu_frame(
        &self,
        gpu: &slc_wgpu::GpuContext,
        r: &Resolved,
    ) -> anyhow::Result<slc_wgpu::frame::GpuVplFrame> {
        let desc = slc_wgpu::frame::FrameDesc {
            width: r.width,
            height: r.height,
            rsm_size: r.rsm_size,
            shadow_size: self.shadow_size.unwrap_or(DEFAULT_SHADOW_SIZE),
            min_distance: self.min_distance,
        };
        slc_wgpu::frame::GpuVplFrame::new(gpu, &r.scene, &desc).map_err(anyhow::Error::from)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::{CommandFactory, Parser};

    #[derive(Parser)]
    struct Flags {
        #[command(flatten)]
        scene: SceneArgs,
    }

    /// `--tile` and `--shadow-size` are options (so that a default value
    /// given explicitly is still refused by the path tracer,
    /// [`SceneArgs::vpl_only_flags`]): their help states the defaults the
    /// code applies.
    #[test]
    fn help_states_the_defaults_applied() {
        let help = Flags::command().render_help().to_string();
        let tile = format!("(CPU backend) [default: {}]", VplSettings::default().tile);
        let shadow = format!("shadow rays) [default: {DEFAULT_SHADOW_SIZE}]");
        assert!(help.contains(&tile) && help.contains(&shadow), "{help}");
        let f = Flags::parse_from(["t", "--app", "pt", "--tile", "4"]);
        assert!(f.scene.vpl_only_flags().is_err());
        assert_eq!(Flags::parse_from(["t"]).scene.tile(), VplSettings::default().tile);
    }
}
