//! The GPU connection: instance, adapter, device and queue.
//!
//! Headless by default (no window, no display handle) so tests, the study
//! harness and CI render off-screen on whatever adapter the machine has,
//! including Mesa's software Vulkan driver (lavapipe) on machines with no GPU.
//! The environment variables wgpu documents are honoured: `WGPU_BACKEND`
//! (`vulkan`, `gl`, ...), `WGPU_POWER_PREF` and `WGPU_ADAPTER_NAME`.

use std::fmt;

/// How to get an adapter on a machine without a GPU; part of every
/// "no adapter" message so the reader knows what to do next.
pub const INSTALL_HINT: &str = "to render without a GPU, install Mesa's software Vulkan driver \
     (lavapipe): `sudo apt-get install mesa-vulkan-drivers libvulkan1` (Debian/Ubuntu); \
     alternatively the GL backend through llvmpipe: `sudo apt-get install libegl1 libegl-mesa0 \
     libgl1-mesa-dri` and run with WGPU_BACKEND=gl";

/// Why no GPU device could be created.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    /// No adapter on the enabled backends (or none matching `WGPU_ADAPTER_NAME`).
    #[error("no GPU adapter found on backends {backends:?} ({reason}); {hint}", hint = INSTALL_HINT)]
    NoAdapter { backends: wgpu::Backends, reason: String },
    /// An adapter exists but refused to create a device.
    #[error("adapter \"{adapter}\" could not create a device")]
    RequestDevice {
        adapter: String,
        #[source]
        source: wgpu::RequestDeviceError,
    },
}

impl crate::error::Kind for GpuError {
    /// The machine, not the input: no adapter, or one that refused.
    fn kind(&self) -> crate::error::ErrorKind {
        crate::error::ErrorKind::Runtime
    }
}

/// What `doctor` prints about the adapter rendering will use.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AdapterSummary {
    /// e.g. "llvmpipe (LLVM 15.0.6, 256 bits)" for lavapipe.
    pub name: String,
    pub backend: wgpu::Backend,
    /// `Cpu` for software rasterisers such as lavapipe.
    pub device_type: wgpu::DeviceType,
}

impl AdapterSummary {
    pub fn from_info(info: &wgpu::AdapterInfo) -> Self {
        Self { name: info.name.clone(), backend: info.backend, device_type: info.device_type }
    }

    /// True for software rasterisers (lavapipe, llvmpipe, WARP).
    pub fn is_software(&self) -> bool {
        self.device_type == wgpu::DeviceType::Cpu
    }
}

impl fmt::Display for AdapterSummary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} ({:?}, {:?})", self.name, self.backend, self.device_type)
    }
}

/// Instance, adapter, device and queue, created together.
///
/// wgpu's handles are cheap reference-counted clones, so other parts of the
/// program (the egui renderer, a second [`crate::render::Renderer`]) can clone
/// `device` and `queue` freely.
#[derive(Debug, Clone)]
pub struct GpuContext {
    pub instance: wgpu::Instance,
    pub adapter: wgpu::Adapter,
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
}

impl GpuContext {
    /// A context without any window: for capture, tests and benchmarks.
    /// Blocks until the device is ready (a fraction of a second on lavapipe).
    pub fn new_headless() -> Result<Self, GpuError> {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let adapter = pollster::block_on(request_adapter(&instance, None))?;
        let (device, queue) = pollster::block_on(request_device(&adapter))?;
        Ok(Self { instance, adapter, device, queue })
    }

    /// Wraps objects created elsewhere, e.g. by the windowed demo, which must
    /// create its instance with a display handle and pick an adapter that can
    /// present to its surface (see [`request_adapter`] and [`request_device`]).
    pub fn from_parts(
        instance: wgpu::Instance,
        adapter: wgpu::Adapter,
        device: wgpu::Device,
        queue: wgpu::Queue,
    ) -> Self {
        Self { instance, adapter, device, queue }
    }

    pub fn summary(&self) -> AdapterSummary {
        AdapterSummary::from_info(&self.adapter.get_info())
    }
}

/// Picks an adapter honouring `WGPU_ADAPTER_NAME` (substring, case-insensitive)
/// and `WGPU_POWER_PREF`; pass the window's surface when presenting.
pub async fn request_adapter(
    instance: &wgpu::Instance,
    compatible_surface: Option<&wgpu::Surface<'_>>,
) -> Result<wgpu::Adapter, GpuError> {
    let backends = wgpu::Backends::from_env().unwrap_or_default();
    if let Ok(wanted) = std::env::var("WGPU_ADAPTER_NAME") {
        let wanted = wanted.to_lowercase();
        let adapters = instance.enumerate_adapters(backends).await;
        let names: Vec<String> = adapters.iter().map(|a| a.get_info().name).collect();
        return adapters
            .into_iter()
            .filter(|a| compatible_surface.is_none_or(|s| a.is_surface_supported(s)))
            .find(|a| a.get_info().name.to_lowercase().contains(&wanted))
            .ok_or_else(|| GpuError::NoAdapter {
                backends,
                reason: format!("WGPU_ADAPTER_NAME={wanted:?} matches none of {names:?}"),
            });
    }
    instance
        .request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::from_env().unwrap_or_default(),
            force_fallback_adapter: false,
            compatible_surface,
            ..Default::default()
        })
        .await
        .map_err(|e| GpuError::NoAdapter { backends, reason: e.to_string() })
}

/// The device the renderer needs: WebGPU defaults, nothing optional, so any
/// adapter (lavapipe, GL through llvmpipe, a real GPU) qualifies.
pub async fn request_device(adapter: &wgpu::Adapter) -> Result<(wgpu::Device, wgpu::Queue), GpuError> {
    adapter
        .request_device(&wgpu::DeviceDescriptor {
            label: Some("surfacelab device"),
            required_features: wgpu::Features::empty(),
            // Downlevel limits (so GL qualifies too), with the adapter's
            // texture sizes so large captures and big windows work.
            required_limits: wgpu::Limits::downlevel_defaults().using_resolution(adapter.limits()),
            ..Default::default()
        })
        .await
        .map_err(|source| GpuError::RequestDevice { adapter: adapter.get_info().name, source })
}

/// Looks for an adapter without creating a device: what `doctor` reports.
pub fn probe_adapter() -> Result<AdapterSummary, GpuError> {
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapter = pollster::block_on(request_adapter(&instance, None))?;
    Ok(AdapterSummary::from_info(&adapter.get_info()))
}

/// The window surface format to ask for: the first sRGB one the surface
/// offers (colours then blend in linear space, as in captures), else the
/// first offered (the renderer then encodes sRGB in its shaders).
pub fn preferred_surface_format(offered: &[wgpu::TextureFormat]) -> Option<wgpu::TextureFormat> {
    offered.iter().copied().find(wgpu::TextureFormat::is_srgb).or_else(|| offered.first().copied())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn surface_format_prefers_srgb() {
        use wgpu::TextureFormat::{Bgra8Unorm, Bgra8UnormSrgb, Rgba16Float};
        assert_eq!(preferred_surface_format(&[Bgra8Unorm, Bgra8UnormSrgb]), Some(Bgra8UnormSrgb));
        assert_eq!(preferred_surface_format(&[Rgba16Float, Bgra8Unorm]), Some(Rgba16Float));
        assert_eq!(preferred_surface_format(&[]), None);
    }

    #[test]
    fn no_adapter_message_says_how_to_install_lavapipe() {
        let e = GpuError::NoAdapter { backends: wgpu::Backends::VULKAN, reason: "none".into() };
        assert!(e.to_string().contains("apt-get install mesa-vulkan-drivers libvulkan1"));
    }
}
