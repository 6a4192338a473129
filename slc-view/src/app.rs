//! The window and its frame loop (winit's [`ApplicationHandler`]): one
//! wgpu device for the surface and slc's frame, each redraw recording the
//! GPU VPL frame ([`GpuVplFrame::record_timed`]), the present pass and the
//! egui overlay into one encoder.

use crate::controls::{Controls, VPL_EDGES};
use crate::present::Present;
use crate::{ViewError, ViewOptions, ViewSummary};
use slc_core::range::CullKind;
use slc_scene::scene::{Camera, PrimaryLight};
use slc_scene::temporal::TemporalSettings;
use slc_wgpu::GpuContext;
use slc_wgpu::frame::{FrameDesc, GpuVplFrame, StageTime};
use std::sync::Arc;
use std::time::Instant;
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::{ElementState, MouseButton, WindowEvent};
use winit::event_loop::ActiveEventLoop;
use winit::keyboard::{Key, NamedKey};
use winit::window::{Window, WindowId};

/// The event handler: the options, then the running state once the window
/// exists, and the first error (which ends the loop).
pub struct App {
    opts: ViewOptions,
    state: Option<State>,
    pub(crate) error: Option<ViewError>,
    pub(crate) summary: ViewSummary,
}

impl App {
    pub fn new(opts: ViewOptions) -> App {
        App { opts, state: None, error: None, summary: ViewSummary::default() }
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, e: ViewError) {
        self.error.get_or_insert(e);
        event_loop.exit();
    }
}

impl ApplicationHandler for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.state.is_none() {
            match State::new(event_loop, &self.opts) {
                Ok(s) => {
                    self.summary.adapter = s.gpu.describe();
                    self.state = Some(s);
                }
                Err(e) => self.fail(event_loop, e),
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
        let Some(s) = self.state.as_mut() else { return };
        let consumed = s.egui_state.on_window_event(&s.window, &event).consumed;
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::Resized(size) => s.resize(size),
            WindowEvent::KeyboardInput { event, .. }
                if !consumed && event.state == ElementState::Pressed =>
            {
                if event.logical_key == Key::Named(NamedKey::Escape) {
                    event_loop.exit();
                } else {
                    s.controls.key(&event.logical_key);
                }
            }
            WindowEvent::MouseInput { state, button: MouseButton::Left, .. } => {
                s.dragging = state == ElementState::Pressed && !consumed
            }
            WindowEvent::CursorMoved { position, .. } => {
                let p = (position.x as f32, position.y as f32);
                if let (true, Some(last)) = (s.dragging, s.cursor) {
                    s.controls.drag((p.0 - last.0, p.1 - last.1), s.config.width as f32);
                }
                s.cursor = Some(p);
            }
            WindowEvent::RedrawRequested => match s.redraw(&self.opts) {
                Ok(done) => {
                    self.summary.frames = s.frame_index;
                    self.summary.last_stage_times.clone_from(&s.stage_times);
                    if done {
                        event_loop.exit();
                    }
                }
                Err(e) => self.fail(event_loop, e),
            },
            _ => {}
        }
    }

    fn about_to_wait(&mut self, _: &ActiveEventLoop) {
        if let Some(s) = &self.state {
            s.window.request_redraw();
        }
    }
}

/// Everything a running window holds.
struct State {
    window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    /// The format the present pass and egui draw in (non-sRGB).
    view_format: wgpu::TextureFormat,
    gpu: GpuContext,
    frame: GpuVplFrame,
    desc: FrameDesc,
    present: Present,
    egui_ctx: egui::Context,
    egui_state: egui_winit::State,
    egui_renderer: egui_wgpu::Renderer,
    controls: Controls,
    /// Frames presented.
    frame_index: u32,
    last: Instant,
    /// Smoothed seconds per frame.
    frame_seconds: f32,
    stage_times: Option<Vec<StageTime>>,
    dragging: bool,
    cursor: Option<(f32, f32)>,
    /// The light, camera and accumulation the frame last had: only a
    /// change is passed on (a moved light is a reported change for the
    /// temporal stage, and must not be one every frame).
    shown: Option<(PrimaryLight, Camera, bool)>,
}

impl State {
    fn new(event_loop: &ActiveEventLoop, opts: &ViewOptions) -> Result<State, ViewError> {
        let attributes = Window::default_attributes()
            .with_title("slc view")
            .with_inner_size(PhysicalSize::new(opts.width, opts.height));
        let window = Arc::new(
            event_loop.create_window(attributes).map_err(|e| ViewError::Window(e.to_string()))?,
        );
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_with_display_handle_from_env(
                Box::new(event_loop.owned_display_handle()),
            ));
        let surface = instance
            .create_surface(window.clone())
            .map_err(|e| ViewError::Window(format!("no surface for the window: {e}")))?;
        let adapter = slc_wgpu::pick_adapter(&instance, Some(&surface)).map_err(|e| match e {
            slc_wgpu::GpuError::NoAdapter(why) => ViewError::NoAdapter(why),
            e => e.into(),
        })?;
        let gpu = GpuContext::open(&adapter)?;
        // The swap chain: 8-bit, drawn through a non-sRGB view (the present
        // pass encodes once).
        let caps = surface.get_capabilities(&adapter);
        use wgpu::TextureFormat as T;
        let preferred = [T::Bgra8Unorm, T::Rgba8Unorm, T::Bgra8UnormSrgb, T::Rgba8UnormSrgb];
        let format = preferred
            .into_iter()
            .find(|f| caps.formats.contains(f))
            .or(caps.formats.first().copied())
            .ok_or_else(|| {
                ViewError::NoAdapter(format!(
                    "{} cannot present to this window",
                    adapter.get_info().name
                ))
            })?;
        let view_format = format.remove_srgb_suffix();
        let size = window.inner_size();
        let config = wgpu::SurfaceConfiguration {
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            format,
            color_space: wgpu::SurfaceColorSpace::Auto,
            width: size.width.max(1),
            height: size.height.max(1),
            present_mode: if opts.frames.is_some() {
                wgpu::PresentMode::AutoNoVsync
            } else {
                wgpu::PresentMode::AutoVsync
            },
            desired_maximum_frame_latency: 2,
            alpha_mode: caps.alpha_modes.first().copied().unwrap_or(wgpu::CompositeAlphaMode::Auto),
            view_formats: if view_format == format { Vec::new() } else { vec![view_format] },
        };
        surface.configure(&gpu.device, &config);
        let desc = FrameDesc {
            width: opts.width,
            height: opts.height,
            rsm_size: opts.rsm_size,
            shadow_size: opts.shadow_size,
            min_distance: opts.min_distance,
        };
        let frame = GpuVplFrame::new(&gpu, &opts.scene, &desc)?;
        let mut present = Present::new(&gpu.device, view_format).map_err(ViewError::Setting)?;
        present.bind(&gpu.device, frame.output());
        let egui_ctx = egui::Context::default();
        let egui_state = egui_winit::State::new(
            egui_ctx.clone(),
            egui::ViewportId::ROOT,
            &window,
            Some(window.scale_factor() as f32),
            None,
            None,
        );
        let egui_renderer = egui_wgpu::Renderer::new(
            &gpu.device,
            view_format,
            egui_wgpu::RendererOptions::default(),
        );
        let mut controls = Controls::new(
            opts.settings,
            opts.exposure,
            opts.scene.primary,
            opts.scene.camera,
            opts.scene.diagonal(),
            opts.rsm_size,
        );
        controls.animate = opts.animate;
        controls.temporal = opts.temporal;
        controls.orbit = opts.orbit;
        let state = State {
            window,
            surface,
            config,
            view_format,
            gpu,
            frame,
            desc,
            present,
            egui_ctx,
            egui_state,
            egui_renderer,
            controls,
            frame_index: 0,
            last: Instant::now(),
            frame_seconds: 0.0,
            stage_times: None,
            dragging: false,
            cursor: None,
            shown: None,
        };
        state.gpu.take_errors()?;
        Ok(state)
    }

    fn resize(&mut self, size: PhysicalSize<u32>) {
        if size.width > 0 && size.height > 0 {
            self.config.width = size.width;
            self.config.height = size.height;
            self.surface.configure(&self.gpu.device, &self.config);
        }
    }

    /// One frame: the light and settings of the controls, the GPU frame,
    /// the present pass and the overlay. `true` when `--frames` are done
    /// (the last one saved as the screenshot, when asked).
    fn redraw(&mut self, opts: &ViewOptions) -> Result<bool, ViewError> {
        let now = Instant::now();
        let dt = now.duration_since(self.last).as_secs_f32();
        self.last = now;
        self.frame_seconds =
            if self.frame_seconds == 0.0 { dt } else { 0.9 * self.frame_seconds + 0.1 * dt };
        // With --frames the light moves by a fixed step per frame, so a
        // screenshot does not depend on the machine's speed.
        self.controls.tick(if opts.frames.is_some() { 1.0 / 60.0 } else { dt });
        // The frame follows the window's size (not with --frames, whose
        // screenshot has the asked size) and the VPL count.
        let size = if opts.frames.is_some() {
            (self.desc.width, self.desc.height)
        } else {
            (self.config.width, self.config.height)
        };
        if self.controls.rsm_edge != self.desc.rsm_size
            || size != (self.desc.width, self.desc.height)
        {
            (self.desc.rsm_size, self.desc.width, self.desc.height) =
                (self.controls.rsm_edge, size.0, size.1);
            self.frame = GpuVplFrame::new(&self.gpu, &opts.scene, &self.desc)?;
            self.present.bind(&self.gpu.device, self.frame.output());
            self.stage_times = None;
            self.shown = None;
        }
        let (light, camera, temporal) =
            (self.controls.light(), self.controls.camera(), self.controls.temporal);
        let shown = self.shown.unwrap_or((opts.scene.primary, opts.scene.camera, false));
        if self.shown.is_none() || shown.0 != light {
            self.frame.set_primary(&light)?;
        }
        if self.shown.is_none() || shown.1 != camera {
            self.frame.set_camera(&camera)?;
        }
        if self.shown.is_none() || shown.2 != temporal {
            self.frame.set_temporal(temporal.then(TemporalSettings::default))?;
        }
        self.shown = Some((light, camera, temporal));
        let settings = self.controls.frame_settings(self.frame_index);
        // The controls' CPU-frame settings into the frame's own.
        let st = slc_wgpu::frame::indirect_settings(&settings, self.frame.min_distance())?;
        let last = opts.frames.is_some_and(|n| self.frame_index + 1 >= n);
        if last && let Some(path) = &opts.screenshot {
            // The last frame is read back and saved (with the exposure and
            // the display mapping the window uses).
            let out = self.frame.render(&st)?;
            out.image
                .write_png(path, self.controls.exposure)
                .map_err(|e| ViewError::Output(e.to_string()))?;
            self.frame_index += 1;
            return Ok(true);
        }
        let gpu = self.gpu.clone();
        let mut encoder = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("slc view frame"),
        });
        let timed = self.frame.record_timed(&mut encoder, &st)?;
        let surface_texture = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(t)
            | wgpu::CurrentSurfaceTexture::Suboptimal(t) => t,
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                // Resized or lost: configure again and draw the next frame.
                self.surface.configure(&gpu.device, &self.config);
                gpu.queue.submit([encoder.finish()]);
                return Ok(false);
            }
            wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => {
                gpu.queue.submit([encoder.finish()]);
                return Ok(false);
            }
            wgpu::CurrentSurfaceTexture::Validation => {
                return Err(ViewError::Gpu("the surface's texture failed validation".into()));
            }
        };
        let target = surface_texture.texture.create_view(&wgpu::TextureViewDescriptor {
            format: Some(self.view_format),
            ..Default::default()
        });
        let target_size = (self.config.width, self.config.height);
        self.present.record(
            &gpu.queue,
            &mut encoder,
            &target,
            (self.desc.width, self.desc.height),
            target_size,
            self.controls.exposure,
        );
        self.overlay(&mut encoder, &target, target_size);
        gpu.queue.submit([encoder.finish()]);
        self.window.pre_present_notify();
        gpu.queue.present(surface_texture);
        if timed {
            self.stage_times = self.frame.stage_times()?;
        }
        self.gpu.take_errors()?;
        self.frame_index += 1;
        Ok(opts.frames.is_some_and(|n| self.frame_index >= n))
    }

    /// The egui panel: adapter, frame rate, per-stage GPU times, controls.
    fn overlay(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        (w, h): (u32, u32),
    ) {
        let input = self.egui_state.take_egui_input(&self.window);
        let (c, fps) = (&mut self.controls, 1.0 / self.frame_seconds.max(1e-6));
        let (adapter, times, frame_ms) =
            (self.gpu.describe(), &self.stage_times, 1e3 * self.frame_seconds);
        let mut output = self.egui_ctx.run_pass(input, |ctx| {
            egui::Window::new("slc")
                .default_pos([8.0, 8.0])
                .show(ctx, |ui| panel(ui, c, &adapter, fps, frame_ms, times));
        });
        self.egui_state.handle_platform_output(&self.window, output.platform_output);
        let jobs = self.egui_ctx.tessellate(output.shapes, output.pixels_per_point);
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: [w, h],
            pixels_per_point: output.pixels_per_point,
        };
        let (device, queue) = (&self.gpu.device, &self.gpu.queue);
        // Drained: epaint checks (in debug builds) that every delta is applied.
        for (id, deltas) in output.textures_delta.set.drain() {
            for delta in &deltas {
                self.egui_renderer.update_texture(device, queue, id, delta);
            }
        }
        self.egui_renderer.update_buffers(device, queue, encoder, &jobs, &screen);
        {
            let pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("slc view overlay"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: target,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations { load: wgpu::LoadOp::Load, store: wgpu::StoreOp::Store },
                })],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            self.egui_renderer.render(&mut pass.forget_lifetime(), &jobs, &screen);
        }
        for id in output.textures_delta.free.drain() {
            self.egui_renderer.free_texture(&id);
        }
    }
}

/// The overlay's contents.
fn panel(
    ui: &mut egui::Ui,
    c: &mut Controls,
    adapter: &str,
    fps: f32,
    frame_ms: f32,
    times: &Option<Vec<StageTime>>,
) {
    ui.label(adapter);
    ui.label(format!("{fps:.1} frames/s ({frame_ms:.1} ms)"));
    match times {
        Some(times) => {
            egui::Grid::new("stages").num_columns(2).show(ui, |ui| {
                for t in times {
                    ui.label(t.name);
                    ui.label(format!("{:.3} ms", t.ms));
                    ui.end_row();
                }
                ui.label("total");
                ui.label(format!("{:.3} ms", times.iter().map(|t| t.ms).sum::<f64>()));
                ui.end_row();
            });
        }
        None => {
            ui.label("per-pass GPU times: this adapter has no usable timestamps");
        }
    }
    ui.separator();
    ui.horizontal(|ui| {
        ui.selectable_value(&mut c.kind, CullKind::Stochastic, "slc [1]");
        ui.selectable_value(&mut c.kind, CullKind::Clamped, "clamp [2]");
        ui.selectable_value(&mut c.kind, CullKind::None, "none [3]");
    });
    match c.kind {
        CullKind::Clamped => ui.add(
            egui::Slider::new(&mut c.range, 0.005..=2.0).logarithmic(true).text("range R [+/-]"),
        ),
        _ => ui.add(
            egui::Slider::new(&mut c.error_bound, 0.0002..=0.5)
                .logarithmic(true)
                .text("error bound ε [+/-]"),
        ),
    };
    ui.checkbox(&mut c.settings.denoise, "denoise [d]");
    ui.checkbox(&mut c.freeze, "freeze ξ [f]");
    egui::ComboBox::from_label("VPLs [v]")
        .selected_text(format!("{}", c.rsm_edge * c.rsm_edge))
        .show_ui(ui, |ui| {
            for e in VPL_EDGES {
                ui.selectable_value(&mut c.rsm_edge, e, format!("{}", e * e));
            }
        });
    ui.checkbox(&mut c.temporal, "temporal accumulation [t]");
    ui.checkbox(&mut c.animate, "animate the light [space]");
    ui.checkbox(&mut c.orbit, "swing the camera [o]");
    ui.label("move the light: arrows, PageUp/PageDown; aim it: drag");
    ui.label("orbit the camera: j/l, tilt: i/k; reset both: r");
}
