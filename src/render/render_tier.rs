//! Capability tiers: which GPU API the browser gave us, decided once at start-up.
//!
//! eframe asks for WebGPU first and falls back to WebGL2 (wgpu's GL backend); the
//! adapter it got names the tier. Everything that differs between tiers is decided
//! here, from the adapter's reported capabilities, and nowhere else. (Model: rerun's
//! `re_renderer/src/device_caps.rs`.)

use eframe::wgpu;

/// The GPU path the app runs on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RenderTier {
    /// WebGPU in the browser: the full path.
    WebGpu,
    /// WebGL2 in the browser (wgpu's GL backend): no compute shaders, no storage
    /// buffers in vertex shaders. The renderer uses neither, so it looks the same.
    WebGl2,
    /// A native desktop window (Vulkan, Metal, DX12 or GL).
    Native,
}

impl RenderTier {
    /// The tier of the adapter eframe chose.
    pub fn of_adapter(adapter: &wgpu::Adapter) -> Self {
        Self::of_backend(adapter.get_info().backend)
    }

    fn of_backend(backend: wgpu::Backend) -> Self {
        if cfg!(target_arch = "wasm32") {
            match backend {
                wgpu::Backend::BrowserWebGpu => Self::WebGpu,
                _ => Self::WebGl2,
            }
        } else {
            Self::Native
        }
    }

    /// The name the automation API reports.
    pub fn name(self) -> &'static str {
        match self {
            Self::WebGpu => "webgpu",
            Self::WebGl2 => "webgl2",
            Self::Native => "native",
        }
    }

    /// What the status line shows.
    pub fn label(self) -> &'static str {
        match self {
            Self::WebGpu => "WebGPU",
            Self::WebGl2 => "WebGL2",
            Self::Native => crate::i18n::ts("render-tier-native"),
        }
    }
}

/// What the renderer may use on this adapter.
#[derive(Clone, Copy, Debug)]
pub struct RenderCaps {
    pub tier: RenderTier,
    /// MSAA samples for the scene: 4 where the colour and depth formats allow it,
    /// else 1 (no anti-aliasing).
    pub msaa_samples: u32,
}

/// Colour format of the offscreen scene image (gamma-encoded by the shader).
pub const SCENE_COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
/// Depth format of the scene; supported by WebGPU and WebGL2 alike.
pub const SCENE_DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

impl RenderCaps {
    pub fn of_adapter(adapter: &wgpu::Adapter) -> Self {
        let supports_4x = |format: wgpu::TextureFormat| {
            adapter
                .get_texture_format_features(format)
                .flags
                .sample_count_supported(4)
        };
        let msaa_samples = if supports_4x(SCENE_COLOR_FORMAT) && supports_4x(SCENE_DEPTH_FORMAT) {
            4
        } else {
            1
        };
        Self {
            tier: RenderTier::of_adapter(adapter),
            msaa_samples,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn native_builds_report_the_native_tier() {
        assert_eq!(
            RenderTier::of_backend(wgpu::Backend::Vulkan),
            RenderTier::Native
        );
        assert_eq!(RenderTier::WebGpu.name(), "webgpu");
        assert_eq!(RenderTier::WebGl2.name(), "webgl2");
    }
}
