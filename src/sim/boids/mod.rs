//! The schooling lab's boid layer (Lim & Tan, SIMBA): the world of point-mass
//! fish, sharks and stingrays; the five urges (containment, alignment,
//! cohesion, separation, obstacle avoidance); the control modes that combine
//! them; the presets of Table 1 (`world::BoidParams`); the metrics the world
//! measures every step. `docs/boids.md` explains the model.

pub mod attention;
pub mod control_mode;
pub mod forces;
pub mod metrics;
pub mod params;
pub mod placement;
pub mod predators;
pub mod shark;
pub mod stingray;
pub mod world;

#[cfg(test)]
mod tests;
