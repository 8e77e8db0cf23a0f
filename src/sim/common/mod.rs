//! What every scene shares: the tank and its rocks, the water's current, the
//! point-mass fish and its steering behaviours (seek, flee, arrive, wander,
//! containment, obstacle avoidance), the neighbour grid, the school's order
//! parameters and the fish world's one clock.

pub mod fish;
pub mod fmath;
pub mod moment;
pub mod obstacle;
pub mod paper_time;
pub mod school_metrics;
pub mod spare;
pub mod spatial_grid;
pub mod steering;
pub mod steering_tuning;
pub mod tank;
pub mod water_current;
