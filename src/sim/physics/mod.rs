//! The physics fish tank (Tu & Terzopoulos §3 bodies steered by the boid
//! layer): the steering layer gives each muscle-driven fish an intended
//! velocity within its body's reach, the motor bridge drives its muscles.

pub mod report;
pub mod world;
