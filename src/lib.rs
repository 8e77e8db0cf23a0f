//! Shoal: a virtual ethology lab. Artificial fishes swim, see and school in a 3D
//! aquarium that runs in the browser (WebAssembly + wgpu + egui).
//!
//! The data flows one way (see ARCHITECTURE.md):
//! `sim` (pure, deterministic) → `lab` (settings + fixed-step clock) → `render`
//! (reads the lab, draws with wgpu) and `ui` (egui panels that edit settings);
//! `app` ties them together; `automation` is the `window.shoal` API; `web` is the
//! browser glue.

// Drawing only: the platform's sin, cos… are fine here (clippy.toml forbids them
// everywhere a run's numbers are computed; see sim::common::fmath).
pub mod a11y;
#[allow(clippy::disallowed_methods)]
pub mod app;
pub mod automation;
pub mod bench;
#[cfg(not(target_arch = "wasm32"))]
pub mod census;
pub mod class;
pub mod clock;
pub mod experiment;
pub mod export;
/// Damaged links and `set()` patches as property tests (issue 35).
#[cfg(test)]
mod fuzz_tests;
pub mod i18n;
pub mod investigation;
pub mod lab;
pub mod metrics_history;
#[allow(clippy::disallowed_methods)] // drawing only (see `app`)
pub mod render;
pub mod scenes;
pub mod settings;
pub mod sim;
/// The soak: a scene for a long simulated time under random changes (issue 35).
pub mod soak;
#[allow(clippy::disallowed_methods)] // drawing only (see `app`)
pub mod ui;

#[cfg(target_arch = "wasm32")]
pub mod web;

pub use app::ShoalApp;
