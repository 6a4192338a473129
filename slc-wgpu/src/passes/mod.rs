//! Passes an engine records into its own command encoder.
//!
//! The engine owns the device, the queue, the frame graph and the G-buffer.
//! It wraps its device once ([`GpuContext::from_device`]: no adapter is
//! requested, no error handler is installed), builds the passes it needs
//! for its image size (each pass keeps a clone of the context: no lifetime
//! ties it to the engine's), and each frame calls their `record` with its
//! own `CommandEncoder`: a pass records compute work only, submits nothing
//! and reads nothing back.
//!
//! - [`IndirectPass`] ([`indirect`]): SLC indirect light from VPLs (an RSM
//!   or a VPL buffer) on the engine's G-buffer: irradiance, and with the
//!   optional material input ([`IndirectMaterials`]) the specular
//!   correction of glossy pixels under the glTF BRDF.
//! - [`DirectPass`] ([`direct`]): SLC direct light from many point, spot,
//!   IES and triangle lights on the engine's G-buffer, the lights movable
//!   every frame.
//! - [`TemporalPass`] ([`temporal`]): temporal accumulation of either
//!   pass's output over frames (reprojection, disocclusion, change
//!   response, moving average), from the camera's previous view-projection.
//!
//! **The G-buffer** ([`GBuffer`]): the surface as the engine's depth buffer
//! (`Depth32Float`, or `R32Float` depth in x) with the view's inverse
//! view-projection, or as world positions (`Rgba32Float` or
//! `Rgba16Float`), plus world normals (`Rgba32Float` or `Rgba16Float`, need
//! not be unit length). Precision: a `Depth32Float` depth unprojects to
//! within `~2⁻²⁴ · d²/n` of the true position for a standard projection
//! (near plane `n`; 10 m at `n = 0.1 m`: 0.06 mm) and to `~2⁻²⁴ · d` with
//! reversed Z; half-float positions step by `2⁻¹⁰` of their magnitude
//! (8 mm at 10 m), which moves shading points off their surfaces; half-float
//! normals hold `~5·10⁻⁴` rad. Every texture must be single-sampled, the
//! pass's size, `TEXTURE_BINDING`; the output `STORAGE_BINDING` in the
//! pass's output format.
//!
//! **Depth**: a texel whose depth is exactly 0 or 1 (either convention's
//! clear value: standard depth clears to 1, reversed Z to 0) is
//! background, so the passes read both conventions without being told
//! which (a surface exactly on the near plane, which the rasterizer clips,
//! reads as background too). Pixel `(x, y)` (row 0 at the top) unprojects
//! at its centre, NDC `(2(x + ½)/w − 1, 1 − 2(y + ½)/h, depth)`, as the
//! rasterizer samples it: a G-buffer rendered with another convention (a
//! half-pixel offset, y down) puts every point a little off its surface.
//! `Surface::Depth`'s `inv_view_proj` must be the inverse of the
//! view-projection the depth was rendered with, and [`GBuffer::eye`] that
//! camera's position: a perspective matrix's inverse maps the clip-space
//! point `(0, 0, 1, 0)` to the eye, and a record whose matrix puts the eye
//! elsewhere (the forward view-projection passed by mistake, or a stale
//! eye) is a [`GpuError::Setting`] naming both points.
//!
//! **Per record**: a wrong format, size or usage is a [`GpuError::Binding`]
//! before anything is recorded, and a limit the device lacks a
//! [`GpuError::Limit`] when the pass is built, before any pipeline is
//! made. A record's uniforms (its settings, the view) travel in a small
//! buffer made for it and are copied into place by the record's own
//! encoder, just before its dispatches: any number of records of a pass may
//! share a submission, each with its own settings. Its bind groups are
//! cached by the views' identity (the same views every frame create none),
//! and the light and intermediate buffers are reused: besides that upload
//! buffer (a few hundred bytes, freed once the GPU has run the record),
//! recording allocates no GPU object.
//!
//! **Frames**: ξ is stratified over frames. Light `i`'s ξ in frame `f` is
//! `xi_for(seed, f, i)` ([`slc_core::xi`]): for a fixed light, the frames
//! `0..2ᵐ` give ξ values one in each of `2ᵐ` equal strata of `[0, 1)`
//! (a scrambled radical inverse), so an average over consecutive frames
//! converges faster than independent frames would, and the frame-to-frame
//! variance of a pixel overstates the error of that average (an engine
//! that estimates its accumulation's error from frame-to-frame variance
//! gets it too pessimistic). Vary `frame` every frame; reuse a `seed` for
//! reproducible images.

pub mod direct;
pub mod indirect;
pub mod temporal;

pub use direct::{
    Dielectric, DirectCounts, DirectInputs, DirectOutputs, DirectPass, DirectPassDesc, DirectReuse,
    DirectSelection, DirectSettings, DirectWalk, MaterialInputs, ShadowRays, Shadows,
};
pub use indirect::{
    IndirectInputs, IndirectMaterials, IndirectPass, IndirectPassDesc, IndirectSettings, VplInput,
    VplSourceDesc, vpl_buffer,
};
pub use slc_shared_shaders::layout::{GpuMaterial, GpuVplRecord};
pub use temporal::{TemporalInputs, TemporalPass, TemporalPassDesc};

#[cfg(doc)]
use crate::GpuContext;
use crate::GpuError;
use glam::{Mat4, Vec3};
pub use slc_scene::culling::Culling;
use slc_shared_shaders::SurfaceSource;
use slc_shared_shaders::layout::ViewParams;

/// The float formats the passes read G-buffer and RSM textures in.
pub(crate) const FLOAT_INPUTS: [wgpu::TextureFormat; 2] =
    [wgpu::TextureFormat::Rgba32Float, wgpu::TextureFormat::Rgba16Float];

/// A record's culling as the kernels take it: `(stochastic, r² of every
/// light when not)`. [`Culling::Reference`] is the VPL frame's, not a
/// pass's: a typed error (the indirect pass's reference is a pass built
/// with `interleaved: false`, recorded under [`Culling::None`]).
pub(crate) fn kernel_form(culling: &Culling) -> Result<(bool, f32), GpuError> {
    match culling.fixed_range2() {
        _ if *culling == Culling::Reference => Err(GpuError::Setting(
            "the passes cull stochastically, clamped or not at all: Culling::Reference is the \
             VPL frame's (a pass's reference is built with interleaved: false, recorded under \
             Culling::None)"
                .into(),
        )),
        None => Ok((true, 0.0)),
        Some(r2) => Ok((false, r2)),
    }
}

/// Where a pass reads the surface of the engine's G-buffer, fixed when the
/// pass is built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SurfaceDesc {
    /// A depth texture: `Depth32Float` (`texture_depth_2d`) or `R32Float`
    /// (depth in x), standard or reversed Z alike: a depth of exactly 0 or
    /// 1 is background (the [`passes`](self) docs).
    Depth {
        /// `Depth32Float` or `R32Float`.
        format: wgpu::TextureFormat,
    },
    /// World positions (`Rgba32Float` or `Rgba16Float`, `w > 0` where a
    /// surface is).
    Position,
}

impl SurfaceDesc {
    /// The kernels' surface source, or a typed error for a depth format the
    /// passes do not read.
    pub(crate) fn source(self) -> Result<SurfaceSource, GpuError> {
        match self {
            SurfaceDesc::Position => Ok(SurfaceSource::Position),
            SurfaceDesc::Depth { format: wgpu::TextureFormat::Depth32Float, .. } => {
                Ok(SurfaceSource::Depth)
            }
            SurfaceDesc::Depth { format: wgpu::TextureFormat::R32Float, .. } => {
                Ok(SurfaceSource::R32Depth)
            }
            SurfaceDesc::Depth { format, .. } => Err(GpuError::Binding {
                name: "surface format",
                expected: "Depth32Float or R32Float".into(),
                found: format!("{format:?}"),
            }),
        }
    }
}

/// The surface of one frame's G-buffer.
#[derive(Clone, Copy, Debug)]
pub enum Surface<'a> {
    /// The depth buffer and the view that made it.
    Depth {
        /// The depth texture's view (the pass's [`SurfaceDesc::Depth`]
        /// format; a depth-stencil texture needs a depth-only view).
        depth: &'a wgpu::TextureView,
        /// The inverse of the view-projection the depth was rendered with
        /// (world from clip; wgpu's clip space: y up, depth in `[0, 1]`),
        /// perspective or orthographic.
        inv_view_proj: Mat4,
    },
    /// World positions.
    Position(&'a wgpu::TextureView),
}

/// An engine's G-buffer for one frame.
#[derive(Clone, Copy, Debug)]
pub struct GBuffer<'a> {
    /// The surface: depth or positions.
    pub surface: Surface<'a>,
    /// World normals (xyz; normalised by the pass), facing the camera.
    pub normal: &'a wgpu::TextureView,
    /// The eye's world position (the indirect pass's denoise weighs by the
    /// distance from it; glossy shading looks from it): with a perspective
    /// depth surface, the point `inv_view_proj` maps the clip-space
    /// `(0, 0, 1, 0)` to (checked).
    pub eye: Vec3,
}

impl GBuffer<'_> {
    /// Checks the G-buffer against the pass's `surface` and size, and makes
    /// the record's [`ViewParams`] (`seed`, `frame`: its random streams).
    pub(crate) fn check(
        &self,
        surface: SurfaceDesc,
        size: (u32, u32),
        seed: u32,
        frame: u32,
    ) -> Result<ViewParams, GpuError> {
        let tex = wgpu::TextureUsages::TEXTURE_BINDING;
        check_view("G-buffer normal", self.normal, size, &FLOAT_INPUTS, tex)?;
        if !self.eye.is_finite() {
            return Err(GpuError::Setting(format!("eye {} must be finite", self.eye)));
        }
        let m = match (self.surface, surface) {
            (Surface::Position(p), SurfaceDesc::Position) => {
                check_view("G-buffer position", p, size, &FLOAT_INPUTS, tex)?;
                Mat4::IDENTITY
            }
            (Surface::Depth { depth, inv_view_proj }, SurfaceDesc::Depth { format, .. }) => {
                check_view("G-buffer depth", depth, size, &[format], tex)?;
                check_inverse_view_projection(inv_view_proj, self.eye)?;
                inv_view_proj
            }
            (Surface::Position(_), SurfaceDesc::Depth { .. }) => {
                return Err(GpuError::Binding {
                    name: "G-buffer surface",
                    expected: "a depth texture (the pass was built for depth)".into(),
                    found: "positions".into(),
                });
            }
            (Surface::Depth { .. }, SurfaceDesc::Position) => {
                return Err(GpuError::Binding {
                    name: "G-buffer surface",
                    expected: "positions (the pass was built for positions)".into(),
                    found: "a depth texture".into(),
                });
            }
        };
        Ok(ViewParams {
            c0: m.x_axis,
            c1: m.y_axis,
            c2: m.z_axis,
            c3: m.w_axis,
            eye: self.eye,
            width: size.0,
            height: size.1,
            shadow_offset: 0.0,
            seed,
            frame,
            f0_d: Vec3::ZERO,
            f90_d: 0.0,
        })
    }

    /// The surface's view.
    pub(crate) fn surface_view(&self) -> &wgpu::TextureView {
        match self.surface {
            Surface::Depth { depth, .. } => depth,
            Surface::Position(p) => p,
        }
    }

    /// The surface's binding name in the kernels' tables.
    pub(crate) fn surface_name(&self) -> &'static str {
        match self.surface {
            Surface::Depth { .. } => "depth_tex",
            Surface::Position(_) => "position_tex",
        }
    }
}

/// Checks that `m` is the inverse of a perspective or orthographic
/// view-projection whose camera is at `eye`: finite and invertible, and,
/// where it is perspective (the last row of its inverse, the clip `w`, has
/// a direction part), mapping the clip-space point `(0, 0, 1, 0)` (the
/// centre of projection) to `eye` within `10⁻³ · (1 + |eye|)`. A forward
/// view-projection passed in its place fails (its inverse is perspective,
/// and its third column is no eye).
pub(crate) fn check_inverse_view_projection(m: Mat4, eye: Vec3) -> Result<(), GpuError> {
    let bad =
        |why: String| Err(GpuError::Setting(format!("Surface::Depth's inv_view_proj: {why}")));
    if !m.is_finite() {
        return bad("must be finite".into());
    }
    let forward = m.inverse();
    if !(m.determinant() != 0.0 && forward.is_finite()) {
        return bad("is singular (it must be the inverse of the view-projection)".into());
    }
    let w_row = forward.row(3);
    if w_row.truncate().length() <= 1e-6 * w_row.w.abs() {
        // Orthographic: no centre of projection to check.
        return Ok(());
    }
    let c = m.z_axis;
    let at = c.truncate() / c.w;
    if !(c.w.abs() > 0.0 && at.is_finite()) || at.distance(eye) > 1e-3 * (1.0 + eye.length()) {
        return bad(format!(
            "maps the centre of projection to {at} but GBuffer::eye is {eye}: pass the inverse of the \
             view-projection the depth was rendered with (world from clip, not clip from world), and that camera's position"
        ));
    }
    Ok(())
}

/// Checks an optional input against how the pass was built: `given` and
/// `built` must agree, else a [`GpuError::Binding`] named `name` that says
/// what the pass expects (`what`: the input; `flag`: the descriptor field
/// that builds the pass for it).
pub(crate) fn check_optional(
    name: &'static str,
    given: bool,
    built: bool,
    what: &str,
    flag: &str,
) -> Result<(), GpuError> {
    match (given, built) {
        (true, true) | (false, false) => Ok(()),
        (false, true) => Err(GpuError::Binding {
            name,
            expected: format!("{what} (the pass was built for it: {flag})"),
            found: "none".into(),
        }),
        (true, false) => Err(GpuError::Binding {
            name,
            expected: format!("none (the pass was built without: {flag})"),
            found: what.into(),
        }),
    }
}

/// Checks that `view` shows a `w × h` 2-D texture of an accepted format with
/// `usage`.
pub(crate) fn check_view(
    name: &'static str,
    view: &wgpu::TextureView,
    (w, h): (u32, u32),
    formats: &[wgpu::TextureFormat],
    usage: wgpu::TextureUsages,
) -> Result<(), GpuError> {
    let t = view.texture();
    let bad = |expected: String, found: String| Err(GpuError::Binding { name, expected, found });
    if !formats.contains(&t.format()) {
        return bad(
            format!(
                "format {}",
                formats.iter().map(|f| format!("{f:?}")).collect::<Vec<_>>().join(" or ")
            ),
            format!("{:?}", t.format()),
        );
    }
    if t.dimension() != wgpu::TextureDimension::D2
        || t.width() != w
        || t.height() != h
        || t.depth_or_array_layers() != 1
        || t.sample_count() != 1
    {
        return bad(
            format!("a single-sampled 2-D texture of {w}×{h}"),
            format!(
                "{:?} {}×{}×{}, {} samples",
                t.dimension(),
                t.width(),
                t.height(),
                t.depth_or_array_layers(),
                t.sample_count()
            ),
        );
    }
    if !t.usage().contains(usage) {
        return bad(format!("usage including {usage:?}"), format!("{:?}", t.usage()));
    }
    Ok(())
}

/// The kernels' output format for a pass's `output_format`:
/// `Rgba16Float` or `Rgba32Float`, else a [`GpuError::Binding`].
pub(crate) fn output_format(
    f: wgpu::TextureFormat,
) -> Result<slc_shared_shaders::OutputFormat, GpuError> {
    match f {
        wgpu::TextureFormat::Rgba16Float => Ok(slc_shared_shaders::OutputFormat::Rgba16Float),
        wgpu::TextureFormat::Rgba32Float => Ok(slc_shared_shaders::OutputFormat::Rgba32Float),
        f => Err(GpuError::Binding {
            name: "output_format",
            expected: "Rgba16Float or Rgba32Float".into(),
            found: format!("{f:?}"),
        }),
    }
}

/// Checks an image size against the 2-D dispatch limits.
pub(crate) fn check_size(
    gpu: &crate::GpuContext,
    what: &str,
    (w, h): (u32, u32),
    tile: u32,
) -> Result<(), GpuError> {
    if w == 0 || h == 0 {
        return Err(GpuError::Setting(format!("{what}: image size {w}×{h} must be non-zero")));
    }
    let lim = &gpu.limits;
    gpu.require("max_texture_dimension_2d", w.max(h) as u64, lim.max_texture_dimension_2d as u64)?;
    gpu.require(
        "max_compute_workgroups_per_dimension",
        w.div_ceil(tile).max(h.div_ceil(tile)) as u64,
        lim.max_compute_workgroups_per_dimension as u64,
    )
}

/// A few bind groups (or sets of them) kept by the identity of what they bind (the engine's
/// views): the same views every frame make no new bind group. Holds at
/// most [`ViewCache::CAPACITY`] entries, the least recently used dropped
/// first (with it its clones of the views).
pub(crate) struct ViewCache<K, V = wgpu::BindGroup> {
    entries: Vec<(K, V)>,
}

impl<K: PartialEq, V: Clone> ViewCache<K, V> {
    /// Entries kept (double- or triple-buffered targets fit).
    pub(crate) const CAPACITY: usize = 4;

    pub(crate) fn new() -> Self {
        ViewCache { entries: Vec::new() }
    }

    /// The bind group for `key`, made by `make` when not cached.
    pub(crate) fn get(&mut self, key: K, make: impl FnOnce() -> V) -> V {
        if let Some(i) = self.entries.iter().position(|(k, _)| *k == key) {
            let e = self.entries.remove(i);
            let g = e.1.clone();
            self.entries.push(e);
            return g;
        }
        let g = make();
        if self.entries.len() == Self::CAPACITY {
            self.entries.remove(0);
        }
        self.entries.push((key, g.clone()));
        g
    }
}
