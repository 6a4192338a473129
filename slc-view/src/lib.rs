//! # slc-view
//!
//! The VPL frame in a real-time window: SLC's variance shows as noise that
//! changes from frame to frame, clamping's bias as darkness that never
//! goes away. A winit window with a wgpu surface shows slc-wgpu's whole
//! GPU frame ([`GpuVplFrame`](slc_wgpu::frame::GpuVplFrame)) every frame,
//! with an egui overlay: the adapter, the frame rate, every pass's GPU time
//! (where the adapter has timestamps), and the controls (method, ε or the
//! clamp range, denoise, frozen ξ, VPL count, the light moved, aimed or
//! animated; see [`controls::Controls::key`]).
//!
//! It is the second embedding example after `slc-wgpu/examples/embed.rs`,
//! and uses only slc-wgpu's public API: the application owns the device
//! (made for its window's surface, wrapped by
//! [`GpuContext::from_device`](slc_wgpu::GpuContext::from_device)), records
//! the frame into its own encoder
//! ([`GpuVplFrame::record_timed`](slc_wgpu::frame::GpuVplFrame::record_timed)),
//! samples [`output`](slc_wgpu::frame::GpuVplFrame::output) in its own
//! present pass and moves the light with
//! [`set_primary`](slc_wgpu::frame::GpuVplFrame::set_primary).
//!
//! ```no_run
//! use slc_scene::scene::Scene;
//! use slc_view::{ViewOptions, run};
//!
//! let summary = run(ViewOptions { frames: Some(30), ..ViewOptions::new(Scene::cornell_box()) })?;
//! println!("{} frames on {}", summary.frames, summary.adapter);
//! # Ok::<(), slc_view::ViewError>(())
//! ```

mod app;
pub mod controls;
mod present;

use slc_scene::scene::Scene;
use slc_scene::vpl::VplSettings;
use slc_wgpu::frame::StageTime;
use std::path::PathBuf;

/// What to show and how.
#[derive(Clone, Debug)]
pub struct ViewOptions {
    /// The scene.
    pub scene: Scene,
    /// Frame (and first window) width in pixels.
    pub width: u32,
    /// Frame (and first window) height in pixels.
    pub height: u32,
    /// RSM edge (`rsm_size²` VPLs; one of [`controls::VPL_EDGES`] to cycle
    /// from it).
    pub rsm_size: u32,
    /// Shadow-map edge.
    pub shadow_size: u32,
    /// Clamp distance of the VPL fall-off (`None`: 1% of the diagonal).
    pub min_distance: Option<f32>,
    /// The first frame's settings (culling, denoise, near field); `frame`
    /// is the viewer's.
    pub settings: VplSettings,
    /// The exposure of the display (and of stochastic culling's error bound
    /// when the viewer switches to it).
    pub exposure: f32,
    /// Start with the light animated.
    pub animate: bool,
    /// Accumulate the indirect light over frames (the key `t` toggles it).
    pub temporal: bool,
    /// Start with the camera swinging about its target (key `o`).
    pub orbit: bool,
    /// Stop after this many frames (the light and camera then move 1/60 s
    /// per frame).
    pub frames: Option<u32>,
    /// With `frames`: save the last frame here as a PNG (the frame read
    /// back, without the overlay).
    pub screenshot: Option<PathBuf>,
}

impl ViewOptions {
    /// `scene` at 512×512 with 65,536 VPLs, a 2048² shadow map and the
    /// default settings, running until the window closes.
    pub fn new(scene: Scene) -> ViewOptions {
        ViewOptions {
            scene,
            width: 512,
            height: 512,
            rsm_size: 256,
            shadow_size: 2048,
            min_distance: None,
            settings: VplSettings::default(),
            exposure: 1.0,
            animate: false,
            temporal: true,
            orbit: false,
            frames: None,
            screenshot: None,
        }
    }
}

/// What a run did.
#[derive(Clone, Debug, Default)]
pub struct ViewSummary {
    /// The adapter, in one line.
    pub adapter: String,
    /// Frames shown (the screenshot's included).
    pub frames: u32,
    /// The last timed frame's stage times (`None` without timestamps).
    pub last_stage_times: Option<Vec<StageTime>>,
}

/// Why the viewer could not run, one line each.
#[derive(Debug, thiserror::Error)]
pub enum ViewError {
    /// No display to open a window on.
    #[error(
        "no display to open a window on ({0}); set DISPLAY or WAYLAND_DISPLAY, or run under xvfb-run"
    )]
    NoDisplay(String),
    /// The window or its surface could not be made.
    #[error("cannot open the window: {0}")]
    Window(String),
    /// No GPU adapter can present to the window.
    #[error("no GPU adapter for the window: {0}")]
    NoAdapter(String),
    /// A bad option.
    #[error("{0}")]
    Setting(String),
    /// The GPU reported an error.
    #[error("GPU error: {0}")]
    Gpu(String),
    /// The screenshot could not be written.
    #[error("cannot write the screenshot: {0}")]
    Output(String),
}

impl From<slc_wgpu::GpuError> for ViewError {
    fn from(e: slc_wgpu::GpuError) -> ViewError {
        match e {
            slc_wgpu::GpuError::Setting(s) => ViewError::Setting(s),
            e => ViewError::Gpu(e.to_string()),
        }
    }
}

/// winit's OS errors read `os error at FILE:LINE: MESSAGE`: the message.
fn os_message(s: &str) -> String {
    match s.strip_prefix("os error at ").and_then(|r| r.split_once(": ")) {
        Some((_, m)) => m.trim_end_matches('.').to_string(),
        None => s.to_string(),
    }
}

/// Opens the window and runs the frame loop until the window closes (or
/// `frames` are done). Must be called on the main thread (winit's rule on
/// most platforms), once per process.
pub fn run(opts: ViewOptions) -> Result<ViewSummary, ViewError> {
    if opts.screenshot.is_some() && opts.frames.is_none() {
        return Err(ViewError::Setting("a screenshot needs a frame count (--frames N)".into()));
    }
    if opts.frames == Some(0) {
        return Err(ViewError::Setting("the frame count must be at least 1".into()));
    }
    opts.settings.validate().map_err(|e| ViewError::Setting(e.to_string()))?;
    opts.scene.validate().map_err(|e| ViewError::Setting(e.to_string()))?;
    let event_loop = winit::event_loop::EventLoop::new()
        .map_err(|e| ViewError::NoDisplay(os_message(&e.to_string())))?;
    event_loop.set_control_flow(winit::event_loop::ControlFlow::Poll);
    let mut app = app::App::new(opts);
    event_loop.run_app(&mut app).map_err(|e| ViewError::Window(e.to_string()))?;
    match app.error {
        Some(e) => Err(e),
        None => Ok(app.summary),
    }
}
