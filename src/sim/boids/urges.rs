//! The forces stage of the boid step: the five urges of each fish
//! (containment, alignment, cohesion, separation, obstacle avoidance) from the
//! school's snapshot and the neighbours it heeds, the weights it gives them
//! (a frightened fish schools closer), and its wander on top of the control
//! mode. Also the steering of a fish without the boid layer (wander, the glass
//! and the rocks).
//!
//! The urges are a pure function of the snapshot, so the attention inspector
//! ([`super::attention`]) replays them after the step instead of storing five
//! vectors per fish.

use glam::Vec3;
use rand_chacha::ChaCha8Rng;

use super::control_mode;
use super::forces::{self, Perception};
use super::neighbours::{Heeded, Snapshot};
use super::params::BoidWorldParams;
use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::ObstacleSet;
use crate::sim::common::steering::{self, SteeringParams};
use crate::sim::common::steering_tuning::SteeringTuning;
use crate::sim::common::tank::Tank;

/// The five urges of one fish as the step computes them, in
/// [`control_mode::Force::ALL`] order: full-strength steering forces (m/s²,
/// each already limited to the maximum force) and how much each is needed now
/// (0–1, what Classic ranks).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Urges {
    forces: [Vec3; 5],
    needs: [f32; 5],
}

impl Urges {
    /// The five urges' full-strength steering forces, m/s².
    pub(super) fn forces(&self) -> &[Vec3; 5] {
        &self.forces
    }

    /// How much each urge is needed now, 0–1.
    pub(super) fn needs(&self) -> &[f32; 5] {
        &self.needs
    }
}

/// What the urges of every fish read in one boid step, the same for all fish:
/// the school's snapshot, the tank, what the fish avoid (rocks, pillars,
/// ledges and stingrays), the senses and limits, and the world's tuning.
#[derive(Clone, Copy, Debug)]
pub(super) struct UrgeInputs<'a> {
    snapshot: &'a Snapshot,
    tank: &'a Tank,
    avoid: &'a ObstacleSet,
    /// Obstacles can only be in a fish's path within this reach, metres.
    avoid_reach_m: f32,
    perception: &'a Perception,
    params: &'a SteeringParams,
    world: &'a BoidWorldParams,
}

impl<'a> UrgeInputs<'a> {
    /// The inputs of this step's urges; `params` are the boid layer's
    /// steering limits ([`boid_steering_params`]).
    pub(super) fn new(
        snapshot: &'a Snapshot,
        tank: &'a Tank,
        avoid: &'a ObstacleSet,
        perception: &'a Perception,
        params: &'a SteeringParams,
        world: &'a BoidWorldParams,
    ) -> Self {
        let avoid_reach_m = params.avoidance_look_ahead_m
            + world.steering.avoidance_clearance_m
            + avoid.max_radius_m();
        Self {
            snapshot,
            tank,
            avoid,
            avoid_reach_m,
            perception,
            params,
            world,
        }
    }

    /// The school's snapshot the urges read.
    pub(super) fn snapshot(&self) -> &'a Snapshot {
        self.snapshot
    }

    /// The boid layer's steering limits.
    pub(super) fn params(&self) -> &'a SteeringParams {
        self.params
    }

    /// The five urges of the fish in `slot` of the snapshot heeding `heeded`
    /// (its neighbours as slots, as [`super::neighbours::Heeding::heed`] gives
    /// them), from the school's snapshot (the start of the step): what the
    /// boid step combines, and what the attention inspector reports.
    pub(super) fn urges_of(&self, slot: usize, heeded: &Heeded) -> Urges {
        let i = slot;
        let (perception, params) = (self.perception, self.params);
        let tuning = &self.world.steering;
        let positions_m = self.snapshot.slot_positions_m();
        let velocities_m_per_s = self.snapshot.slot_velocities_m_per_s();
        let position_m = positions_m[i];
        let velocity_m_per_s = velocities_m_per_s[i];
        let max_force = params.max_force_m_per_s2;
        let neighbours = forces::forces_from_neighbours_with_directions(
            positions_m,
            velocities_m_per_s,
            self.snapshot.slot_directions(),
            i,
            heeded.neighbours(),
            heeded.far_centre_m(),
            perception,
            tuning,
        );
        // Containment: stay in the pond (the papers' meaning). Turn back
        // towards open water when the path leaves the comfortable middle, and,
        // near the glass, sand and surface, the wall algorithm: turn along the
        // wall instead of into it.
        let walls = steering::avoid_walls(
            position_m,
            velocity_m_per_s,
            self.tank,
            self.world.wall_range_m,
            tuning,
        );
        let containment = steering::limit(
            forces::steer_towards(
                velocity_m_per_s
                    + steering::containment(
                        position_m,
                        velocity_m_per_s,
                        self.tank,
                        params.containment_look_ahead_s,
                        self.world.pond_comfort_margin_m,
                        params.max_speed_m_per_s,
                    ),
                velocity_m_per_s,
                perception,
            ) + walls / perception.response_time_s.max(1e-3),
            max_force,
        );
        // Avoidance: the rocks, pillars, ledges and stingrays (rock
        // algorithm) and fish on a collision course (swaying, clusters as one
        // obstacle).
        let avoidance = steering::limit(
            (steering::avoid_obstacles(
                position_m,
                velocity_m_per_s,
                self.avoid.near(position_m, self.avoid_reach_m),
                params.avoidance_look_ahead_m,
                tuning.avoidance_clearance_m,
                params.max_speed_m_per_s,
            ) + forces::avoid_neighbours_facing(
                positions_m,
                velocities_m_per_s,
                self.snapshot.slot_directions()[i],
                i,
                heeded.neighbours(),
                params.max_speed_m_per_s,
                tuning,
            )) / perception.response_time_s.max(1e-3),
            max_force,
        );
        let forces = [
            containment,
            neighbours.alignment_m_per_s2,
            neighbours.cohesion_m_per_s2,
            neighbours.separation_m_per_s2,
            avoidance,
        ];
        let mut needs = control_mode::needs_from_forces(&forces, max_force);
        // Classic ranks the neighbour urges by how much each is needed
        // (0–1), not by their forces, which saturate inside a school.
        needs[2] = neighbours.cohesion_need;
        needs[3] = neighbours.separation_need;
        Urges { forces, needs }
    }
}

/// The steering limits of the boid layer: the world's `params`, with the top
/// speed and maximum force the sliders set in `perception`.
pub(super) fn boid_steering_params(
    params: &SteeringParams,
    perception: &Perception,
) -> SteeringParams {
    SteeringParams {
        max_speed_m_per_s: perception.max_speed_m_per_s,
        max_force_m_per_s2: perception.max_force_m_per_s2,
        min_speed_m_per_s: perception.min_speed_m_per_s,
        ..*params
    }
}

/// The weights a fish uses this step: the sliders' `weights`, and a frightened
/// fish's closer school (cohesion up, separation down, by the world's fear
/// factors).
pub(super) fn urge_weights(weights: [f32; 5], fleeing: bool, world: &BoidWorldParams) -> [f32; 5] {
    let mut weights = weights;
    if fleeing {
        weights[2] = (weights[2] * world.fear_cohesion_factor).min(100.0);
        weights[3] *= world.fear_separation_factor;
    }
    weights
}

/// A boid fish's wander push, m/s², on the urges' scale: a full slider
/// (`wander_weight` 100) gives the same share of the maximum force as a full
/// alignment or cohesion slider. Draws from `rng` only when the weight is
/// above zero.
pub(super) fn boid_wander(
    fish: &mut Fish,
    rng: &mut ChaCha8Rng,
    wander_weight: f32,
    perception: &Perception,
    params: &SteeringParams,
    tuning: &SteeringTuning,
) -> Vec3 {
    if wander_weight > 0.0 {
        steering::limit(
            steering::wander(fish, rng, params, tuning) / perception.response_time_s.max(1e-3),
            params.max_force_m_per_s2,
        ) * (wander_weight.min(100.0) / 100.0 * control_mode::WANDER_SHARE_AT_FULL_WEIGHT)
    } else {
        Vec3::ZERO
    }
}

/// Containment (stay off the glass, floor and surface) and obstacle avoidance for
/// `fish` on the wander path.
pub(super) fn glass_and_rock_forces(
    fish: &Fish,
    tank: &Tank,
    obstacles: &ObstacleSet,
    params: &SteeringParams,
    tuning: &SteeringTuning,
) -> (Vec3, Vec3) {
    let reach_m =
        params.avoidance_look_ahead_m + tuning.avoidance_clearance_m + obstacles.max_radius_m();
    let containment = steering::containment(
        fish.position_m,
        fish.velocity_m_per_s,
        tank,
        params.containment_look_ahead_s,
        params.containment_margin_m,
        params.max_speed_m_per_s,
    );
    let avoidance = steering::avoid_obstacles(
        fish.position_m,
        fish.velocity_m_per_s,
        obstacles.near(fish.position_m, reach_m),
        params.avoidance_look_ahead_m,
        tuning.avoidance_clearance_m,
        params.max_speed_m_per_s,
    );
    (containment, avoidance)
}
