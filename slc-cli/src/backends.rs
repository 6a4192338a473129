//! Backend selection at run time: the CPU or the GPU path tracer
//! ([`slc_scene::backend`]) behind one boxed object. The VPL application
//! runs the CPU's frame or the GPU's whole frame
//! ([`slc_wgpu::frame::GpuVplFrame`]), chosen in `render` and `bench`.

use clap::ValueEnum;
use slc_cpu::pt::CpuPathTracer;
use slc_scene::backend::DynPathTracer;
use slc_scene::pt::PtScene;
use slc_wgpu::passes::ShadowRays;
use slc_wgpu::{GpuContext, GpuOptions};

/// Which backend.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum Backend {
    /// rayon on the CPU.
    Cpu,
    /// wgpu compute (a real GPU, or Mesa's lavapipe).
    Gpu,
}

/// The GPU context when `backend` is `gpu`; its error says how to fall back.
pub fn gpu_context(backend: Backend) -> anyhow::Result<Option<GpuContext>> {
    gpu_context_with(backend, false)
}

/// [`gpu_context`], asking for ray queries when `ray_query` (`--ray-query`;
/// refused on the CPU backend).
pub fn gpu_context_with(backend: Backend, ray_query: bool) -> anyhow::Result<Option<GpuContext>> {
    match backend {
        Backend::Cpu if ray_query => {
            anyhow::bail!("--ray-query: ray queries are the GPU's (add --backend gpu)")
        }
        Backend::Cpu => Ok(None),
        Backend::Gpu => GpuContext::with_options(&GpuOptions { ray_query })
            .map(Some)
            .map_err(anyhow::Error::from),
    }
}

/// The path tracer of `pts` at `width × height`: the GPU's when `gpu`
/// holds a context (its shadow rays as ray queries when `ray_query`), else
/// the CPU's; `grid` turns its grids over the light hierarchy on or off
/// (`--grid`; `None`: the backend's default).
pub fn path_tracer(
    gpu: Option<&GpuContext>,
    pts: &PtScene,
    (width, height): (u32, u32),
    ray_query: bool,
    grid: Option<bool>,
) -> anyhow::Result<Box<dyn DynPathTracer>> {
    let rays = if ray_query { ShadowRays::RayQuery } else { ShadowRays::Software };
    match gpu {
        Some(g) => {
            let mut t = slc_wgpu::pt::GpuPt::with_shadow_rays(g, pts, width, height, rays)?;
            if let Some(on) = grid {
                t.set_grid(on);
            }
            Ok(Box::new(t))
        }
        None => {
            let mut t = CpuPathTracer::new(pts);
            if let Some(on) = grid {
                t.set_grid(on);
            }
            Ok(Box::new(t))
        }
    }
}

/// Passes per GPU submission batch in time- or spp-bounded loops (one
/// readback per batch); the CPU goes one pass at a time.
pub const GPU_BATCH: u32 = 16;
