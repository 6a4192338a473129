//! Adapter and device setup: works on real GPUs and on Mesa's software
//! Vulkan driver (lavapipe); errors are typed, never panics.

use crate::GpuError;
use std::sync::{Arc, Mutex};

/// A device, its queue, and what adapter it runs on. Cloning is cheap
/// (every field is a reference-counted handle or a small value) and shares
/// the device, the queue and the error log: passes and frames keep a clone
/// instead of borrowing the context.
#[derive(Clone, Debug)]
pub struct GpuContext {
    /// Device.
    pub device: wgpu::Device,
    /// Queue.
    pub queue: wgpu::Queue,
    /// Adapter description.
    pub adapter: wgpu::AdapterInfo,
    /// Limits granted to the device (the adapter's own).
    pub limits: wgpu::Limits,
    /// Whether GPU timestamps can be taken in compute passes.
    pub timestamps: bool,
    /// Whether the device has wgpu's experimental ray queries
    /// (`Features::EXPERIMENTAL_RAY_QUERY`): what the direct pass's
    /// [`ShadowRays::RayQuery`](crate::passes::direct::ShadowRays) needs.
    /// [`GpuContext::open_with`] and [`GpuContext::with_options`] ask for
    /// them with [`GpuOptions::ray_query`]; [`GpuContext::from_device`]
    /// reads them off the device.
    pub ray_query: bool,
    errors: Arc<Mutex<Vec<String>>>,
}

impl GpuContext {
    /// Picks the best adapter (`WGPU_BACKEND`, `WGPU_ADAPTER_NAME` and
    /// `WGPU_POWER_PREF` environment variables are honoured) and opens a
    /// device with the adapter's full limits.
    pub fn new() -> Result<GpuContext, GpuError> {
        GpuContext::with_options(&GpuOptions::default())
    }

    /// [`GpuContext::new`] with `options`.
    pub fn with_options(options: &GpuOptions) -> Result<GpuContext, GpuError> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        GpuContext::open_with(&pick_adapter(&instance, None)?, options)
    }

    /// Opens a device on `adapter` with the adapter's full limits and
    /// timestamp queries where it has them, and installs an error handler
    /// and a device-lost callback that [`GpuContext::take_errors`] reports.
    /// An application that picks its own adapter (one that can present to
    /// its window, as `slc view` does) starts here.
    pub fn open(adapter: &wgpu::Adapter) -> Result<GpuContext, GpuError> {
        GpuContext::open_with(adapter, &GpuOptions::default())
    }

    /// [`GpuContext::open`] with `options`: with
    /// [`GpuOptions::ray_query`], the device also gets wgpu's
    /// experimental ray queries where the adapter has them
    /// ([`GpuContext::ray_query`] says whether it did).
    pub fn open_with(
        adapter: &wgpu::Adapter,
        options: &GpuOptions,
    ) -> Result<GpuContext, GpuError> {
        let info = adapter.get_info();
        let limits = adapter.limits();
        let timestamps = adapter.features().contains(wgpu::Features::TIMESTAMP_QUERY);
        let ray_query = options.ray_query
            && adapter.features().contains(wgpu::Features::EXPERIMENTAL_RAY_QUERY);
        let mut required_features =
            if timestamps { wgpu::Features::TIMESTAMP_QUERY } else { wgpu::Features::empty() };
        let mut experimental_features = wgpu::ExperimentalFeatures::disabled();
        if ray_query {
            required_features |= wgpu::Features::EXPERIMENTAL_RAY_QUERY;
            experimental_features = experimental_ray_query();
        }
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("slc"),
            required_features,
            required_limits: limits.clone(),
            experimental_features,
            ..Default::default()
        }))
        .map_err(|e| GpuError::Device(e.to_string()))?;
        let errors: Arc<Mutex<Vec<String>>> = Arc::default();
        let sink = errors.clone();
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            if let Ok(mut v) = sink.lock() {
                v.push(e.to_string());
            }
        }));
        let lost = errors.clone();
        device.set_device_lost_callback(move |reason, msg| {
            if let Ok(mut v) = lost.lock() {
                v.push(format!("device lost ({reason:?}): {msg}"));
            }
        });
        Ok(GpuContext { device, queue, adapter: info, limits, timestamps, ray_query, errors })
    }

    /// Wraps a device and queue the caller (an engine) already has: no
    /// adapter is requested and no error handler or device-lost callback is
    /// installed (the engine's own stay in place; [`GpuContext::take_errors`]
    /// then reports nothing). Limits, features and the adapter description
    /// come from the device.
    pub fn from_device(device: wgpu::Device, queue: wgpu::Queue) -> GpuContext {
        let adapter = device.adapter_info();
        let limits = device.limits();
        let timestamps = device.features().contains(wgpu::Features::TIMESTAMP_QUERY);
        let ray_query = device.features().contains(wgpu::Features::EXPERIMENTAL_RAY_QUERY);
        GpuContext { device, queue, adapter, limits, timestamps, ray_query, errors: Arc::default() }
    }

    /// One line naming the adapter, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), Vulkan, Cpu".
    pub fn describe(&self) -> String {
        format!("{}, {:?}, {:?}", self.adapter.name, self.adapter.backend, self.adapter.device_type)
    }

    /// Fails with [`GpuError::Limit`] when `need` exceeds the device limit
    /// `have` called `name`.
    pub fn require(&self, name: impl Into<String>, need: u64, have: u64) -> Result<(), GpuError> {
        if need > have { Err(GpuError::Limit { name: name.into(), need, have }) } else { Ok(()) }
    }

    /// Errors the device reported since the last call (validation, out of
    /// memory, device lost), as one [`GpuError::Device`].
    pub fn take_errors(&self) -> Result<(), GpuError> {
        let mut v =
            self.errors.lock().map_err(|_| GpuError::Device("error log poisoned".into()))?;
        if v.is_empty() {
            return Ok(());
        }
        let msg = v.join("; ");
        v.clear();
        Err(GpuError::Device(msg))
    }

    /// Waits for all submitted work.
    pub fn wait(&self) -> Result<(), GpuError> {
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| GpuError::Device(e.to_string()))?;
        self.take_errors()
    }
}

/// How [`GpuContext::open_with`] opens a device.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GpuOptions {
    /// Ask for wgpu's experimental ray queries
    /// (`Features::EXPERIMENTAL_RAY_QUERY`) where the adapter has them,
    /// for the direct pass's hardware shadow rays. wgpu marks them
    /// experimental: not yet held to WebGPU's guarantees on every driver.
    /// Default: no.
    pub ray_query: bool,
}

/// wgpu's opt-in to its experimental features, asked for by
/// [`GpuOptions::ray_query`] only.
#[allow(unsafe_code)]
fn experimental_ray_query() -> wgpu::ExperimentalFeatures {
    // SAFETY: wgpu's token says the caller accepts that experimental
    // features may not uphold its validation guarantees. slc asks for it
    // only when the application sets `GpuOptions::ray_query`, and uses
    // ray queries only as shadow rays through acceleration structures it
    // builds from validated, finite geometry (slc-scene's `Occluders`).
    unsafe { wgpu::ExperimentalFeatures::enabled() }
}

/// The adapter slc runs on, compatible with `surface` when one is given:
/// the one whose name contains `WGPU_ADAPTER_NAME` (case-insensitive)
/// where that variable is set, else wgpu's choice under `WGPU_POWER_PREF`
/// (`WGPU_BACKEND` is the instance's). wgpu's own
/// `initialize_adapter_from_env` panics on a name nothing matches; this
/// says which adapters there are instead.
pub fn pick_adapter(
    instance: &wgpu::Instance,
    surface: Option<&wgpu::Surface<'_>>,
) -> Result<wgpu::Adapter, GpuError> {
    let usable = |a: &wgpu::Adapter| surface.is_none_or(|s| a.is_surface_supported(s));
    if let Some(want) = std::env::var("WGPU_ADAPTER_NAME").ok().filter(|n| !n.is_empty()) {
        let adapters: Vec<wgpu::Adapter> =
            pollster::block_on(instance.enumerate_adapters(wgpu::Backends::all()))
                .into_iter()
                .filter(usable)
                .collect();
        let names: Vec<String> = adapters.iter().map(|a| a.get_info().name).collect();
        return adapters
            .into_iter()
            .find(|a| a.get_info().name.to_lowercase().contains(&want.to_lowercase()))
            .ok_or_else(|| {
                GpuError::NoAdapter(format!(
                    "WGPU_ADAPTER_NAME={want} matches none of the adapters [{}]",
                    names.join(", ")
                ))
            });
    }
    pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
        power_preference: wgpu::PowerPreference::from_env().unwrap_or_default(),
        compatible_surface: surface,
        ..Default::default()
    }))
    .map_err(|e| GpuError::NoAdapter(e.to_string()))
}
