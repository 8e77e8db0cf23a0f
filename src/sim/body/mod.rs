//! The physical fish of Tu & Terzopoulos 1994 §3: a 23-node, 91-spring body with 12
//! muscles (§3.1–3.2), pushed by the water (§3.2), driven by motor controllers (§3.3)
//! and steered in pitch, yaw and roll by pectoral fins (§3.4).
//!
//! Data flow inside this module: motor controllers (swim-MC, turn-MC, added
//! together while turning) → [`BodyCommand`] (muscle
//! contractions + fin angles) → [`FishBody::step`] (springs, water, fins, implicit
//! Euler) → node positions.

pub mod banded_cholesky;
pub mod body_layout;
#[cfg(not(target_arch = "wasm32"))]
pub mod census;
pub mod drive;
pub mod fish_body;
pub mod hydrodynamics;
pub mod motor_bridge;
pub mod motor_controller;
pub mod pectoral_fins;
pub mod physical_fish;
#[cfg(not(target_arch = "wasm32"))]
pub mod swim_trials;
pub mod turn_mc;

#[cfg(test)]
mod tests;

pub use body_layout::{MUSCLE_COUNT, MuscleSegment, NODE_COUNT, SPRING_COUNT, Side};
pub use fish_body::{BodyCommand, BodyParams, FishBody, Integrator};
pub use motor_controller::{
    ControlSampling, SPEED_AT_AMPLITUDE, SwimMc, SwimParams, amplitude_for_speed,
};
pub use pectoral_fins::PectoralFins;
pub use turn_mc::{SteeringMap, TurnDirection, TurnMc, TurnParams};
