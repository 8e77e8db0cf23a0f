//! Rendering: reads the simulation, never writes it. wgpu only; no egui widgets here
//! except the paint callback that puts the 3D view inside egui.

pub mod body_skin;
#[cfg(not(target_arch = "wasm32"))]
pub(crate) mod census;
pub mod detail;
pub mod fish_palette;
pub mod frame_builder;
pub mod mesh;
pub mod orbit_camera;
pub mod profile;
pub mod render_tier;
pub mod scene_renderer;

pub use body_skin::{BodyLook, BodyShape, BodySkin};
pub use detail::SceneDetail;
pub use frame_builder::FrameBuilder;
pub use orbit_camera::{Framing, OrbitCamera};
pub use render_tier::{RenderCaps, RenderTier};
pub use scene_renderer::{FishInstance, SceneCallback, SceneRenderer, SceneUniforms, StaticScene};
