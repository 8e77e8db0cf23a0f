//! The pure simulation of the aquarium: tank, obstacles, fish and how they
//! steer. Nothing in here draws, plays sound or knows about the web: the app
//! reads a [`World`] after each fixed [`World::step`] and renders it.
//!
//! Units are SI throughout (metres, seconds, radians) and every name carries
//! its unit (`speed_m_per_s`, `radius_m`, `dt_secs`). The y axis points up and
//! the sand floor is at y = 0. A run is fully determined by its seed.

pub mod body;
pub mod boids;
pub mod common;
pub mod learning;
pub mod physics;
pub mod reef;
pub mod scene;

pub use body::physical_fish::{BodySpecies, PhysicalFish};
pub use boids::metrics::WorldMetrics;
pub use boids::shark::Shark;
pub use boids::stingray::Stingray;
pub use boids::world::{BoidParams, DT_SECS, World, WorldConfig};
pub use common::fish::Fish;
pub use common::obstacle::Obstacle;
pub use common::school_metrics::SchoolMetrics;
pub use common::spatial_grid::SpatialGrid;
pub use common::steering::SteeringParams;
pub use common::tank::Tank;
pub use physics::world::{HandCommand, PhysicsBehaviour, PhysicsConfig, PhysicsWorld};
pub use scene::{SceneReport, SceneWorld};
