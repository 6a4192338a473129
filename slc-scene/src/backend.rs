//! The contract both backends implement, one trait per application. The
//! CLI and the cross-backend tests program against these traits; each
//! backend builds its implementor from slc-scene data (a [`VplInputs`], a
//! [`PtScene`]) and never from the other backend's types.

use crate::pt::{PtRender, PtSettings};
use crate::vpl::{Shaded, VplSettings};
#[cfg(doc)]
use crate::{pt::PtScene, vpl::VplInputs};

/// How a backend timed its work.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Timing {
    /// Host wall-clock time around the work.
    Wall,
    /// GPU timestamps around the submitted passes.
    GpuTimestamps,
}

/// Application A: indirect irradiance at every G-buffer pixel from the VPLs
/// of the [`VplInputs`] the shader was built for (8×8 interleaved subsets,
/// tiled culling, optionally denoised by the backend).
pub trait IndirectShader {
    /// The backend's error.
    type Error: std::error::Error + Send + Sync + 'static;
    /// The backend, for reports (`"cpu (2 threads)"`, the GPU adapter).
    fn describe(&self) -> String;
    /// Shades one frame. `Shaded::denoised_ms` is `Some` when the backend
    /// already applied the cross-bilateral filter. Takes `&mut self`, as
    /// [`PathTracer::render`] does: a GPU backend records into buffers and
    /// uniform slots it owns, so one frame at a time, without a lock.
    fn shade(&mut self, settings: &VplSettings) -> Result<Shaded, Self::Error>;
}

impl<T: IndirectShader + ?Sized> IndirectShader for &mut T {
    type Error = T::Error;
    fn describe(&self) -> String {
        (**self).describe()
    }
    fn shade(&mut self, settings: &VplSettings) -> Result<Shaded, Self::Error> {
        (**self).shade(settings)
    }
}

/// Application B: progressive path tracing of the [`PtScene`] the tracer
/// was built for.
pub trait PathTracer {
    /// The backend's error.
    type Error: std::error::Error + Send + Sync + 'static;
    /// The backend, for reports.
    fn describe(&self) -> String;
    /// Renders `passes` more passes of one sample per pixel into `acc`.
    /// Pass numbers continue from `acc.passes`, so a render split over calls
    /// equals one call.
    fn render(
        &mut self,
        acc: &mut PtRender,
        settings: &PtSettings,
        passes: u32,
    ) -> Result<Timing, Self::Error>;
}

/// A backend error with its type erased (see [`DynIndirectShader`]).
pub type BoxError = Box<dyn std::error::Error + Send + Sync>;

/// [`IndirectShader`] with its error boxed: object safe, for callers that
/// choose the backend at run time (`Box<dyn DynIndirectShader>`). Every
/// `IndirectShader` is one.
pub trait DynIndirectShader {
    /// [`IndirectShader::describe`].
    fn describe(&self) -> String;
    /// [`IndirectShader::shade`].
    fn shade(&mut self, settings: &VplSettings) -> Result<Shaded, BoxError>;
}

impl<T: IndirectShader> DynIndirectShader for T {
    fn describe(&self) -> String {
        IndirectShader::describe(self)
    }
    fn shade(&mut self, settings: &VplSettings) -> Result<Shaded, BoxError> {
        IndirectShader::shade(self, settings).map_err(Into::into)
    }
}

/// [`PathTracer`] with its error boxed: object safe, for callers that choose
/// the backend at run time. Every `PathTracer` is one.
pub trait DynPathTracer {
    /// [`PathTracer::describe`].
    fn describe(&self) -> String;
    /// [`PathTracer::render`].
    fn render(
        &mut self,
        acc: &mut PtRender,
        settings: &PtSettings,
        passes: u32,
    ) -> Result<Timing, BoxError>;
}

impl<T: PathTracer> DynPathTracer for T {
    fn describe(&self) -> String {
        PathTracer::describe(self)
    }
    fn render(
        &mut self,
        acc: &mut PtRender,
        settings: &PtSettings,
        passes: u32,
    ) -> Result<Timing, BoxError> {
        PathTracer::render(self, acc, settings, passes).map_err(Into::into)
    }
}
