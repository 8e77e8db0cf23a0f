//! The pure simulation of the aquarium: tank, obstacles, fish and how they
//! steer. Nothing in here draws, plays sound or knows about the web: the app
//! reads a [`World`] after each fixed [`World::step`] and renders it.
//!
//! Units are SI throughout (metres, seconds, radians) and every name carries
//! its unit (`speed_m_per_s`, `radius_m`, `dt_secs`). The y axis points up and
//! the sand floor is at y = 0. A run is fully determined by its seed.

pub mod behaviour;
pub mod body;
pub mod boid_forces;
pub mod control_mode;
pub mod courtship;
pub mod environment;
pub mod fish;
pub mod learning;
pub mod mind;
pub mod motor_bridge;
pub mod motor_choice;
pub mod obstacle;
pub mod paper_time;
pub mod perception;
pub mod physical_fish;
pub mod physics_world;
pub mod reef_world;
pub mod scene;
pub mod school_metrics;
pub mod shark;
pub mod spatial_grid;
pub mod steering;
pub mod stingray;
pub mod tank;
pub mod water_current;
pub mod world;
pub mod world_metrics;

pub use fish::Fish;
pub use obstacle::Obstacle;
pub use physical_fish::{BodySpecies, PhysicalFish};
pub use physics_world::{HandCommand, PhysicsBehaviour, PhysicsConfig, PhysicsWorld};
pub use scene::SceneWorld;
pub use school_metrics::SchoolMetrics;
pub use shark::Shark;
pub use spatial_grid::SpatialGrid;
pub use steering::SteeringParams;
pub use stingray::Stingray;
pub use tank::Tank;
pub use world::{BoidParams, DT_SECS, World, WorldConfig};
pub use world_metrics::WorldMetrics;
