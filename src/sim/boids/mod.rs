//! The schooling lab's boid layer (Lim & Tan, SIMBA): the world of point-mass
//! fish, sharks and stingrays; the five urges (containment, alignment,
//! cohesion, separation, obstacle avoidance); the control modes that combine
//! them; the presets of Table 1 (`world::BoidParams`); the metrics the world
//! measures every step. `docs/boids.md` explains the model.
//!
//! `world.rs` holds the stages of the step and their order; each stage owns
//! its state and takes the rest as explicit inputs: placement
//! (`placement::Scenery`), predators and fear (`predators::Predators`,
//! `predators::Fear`), neighbours (`neighbours::Snapshot`,
//! `neighbours::Heeding`), the urges (`urges::UrgeInputs`), the control mode
//! (`control_mode::ControlStage`), the attention inspector's record
//! (`attention::StepLog`) and the metrics (`metrics::WorldMeter`). No stage
//! imports `world.rs`.

pub mod attention;
pub mod control_mode;
pub mod forces;
mod hard_rules;
pub mod metrics;
mod neighbours;
pub mod params;
pub mod placement;
pub mod predators;
pub mod shark;
pub mod stingray;
mod urges;
pub mod world;

#[cfg(test)]
mod tests;
