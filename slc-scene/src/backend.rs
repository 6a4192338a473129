//! The contract both backends implement for the path tracer
//! (application B): the CLI programs against [`PathTracer`], and each
//! backend builds its implementor from slc-scene data (a [`PtScene`]),
//! never from the other backend's types. Application A has no trait: the
//! CPU frame and the GPU's passes take different inputs (a scene's
//! ray-cast G-buffer, an engine's textures) and return [`Shaded`] or
//! textures.

use crate::pt::{PtRender, PtSettings};
#[cfg(doc)]
use crate::{pt::PtScene, vpl::Shaded};

/// How a backend timed its work.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Timing {
    /// Host wall-clock time around the work.
    Wall,
    /// GPU timestamps around the submitted passes.
    GpuTimestamps,
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
    /// equals one call. Takes `&mut self`: a GPU backend records into
    /// buffers and uniform slots it owns, so one render at a time, without
    /// a lock.
    fn render(
        &mut self,
        acc: &mut PtRender,
        settings: &PtSettings,
        passes: u32,
    ) -> Result<Timing, Self::Error>;
}

/// A backend error with its type erased (see [`DynPathTracer`]).
pub type BoxError = Box<dyn std::error::Error + Send + Sync>;

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
