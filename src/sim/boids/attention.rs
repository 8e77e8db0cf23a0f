//! What a fish pays attention to: the neighbours it heeds, its five urges, which
//! of them the control mode applied in the last step, and what came of it.
//!
//! The boid step computes each fish's urges with [`UrgeInputs::urges_of`] from
//! the school's snapshot (everyone's positions and velocities at the start of
//! the step) and the neighbours it heeded; [`Attention::replay`] calls the same
//! function on the same snapshot afterwards, so it reports exactly what the
//! step computed without storing five vectors per fish. What cannot be worked
//! out again (the control mode's dice, wander's random turn, fleeing from a
//! shark that has moved since) the step records for every fish in a
//! [`StepRecord`] (a few bytes each); nothing here changes what the fish do.
//!
//! This is the answer to the "leader fish" misconception (Resnick 1996): no fish
//! follows a leader; each reacts only to the few neighbours it sees.

use glam::Vec3;
use serde::Serialize;

use super::control_mode::{self, ControlMode, Force};
use super::neighbours::Heeded;
use super::urges::UrgeInputs;

/// What one fish did in the last boid step that cannot be worked out again
/// afterwards.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct StepRecord {
    /// Which urges the control mode applied.
    applied: [bool; 5],
    /// Did it flee a shark (which also changes its cohesion and separation
    /// weights, see [`super::urges::urge_weights`])?
    fleeing: bool,
    /// Wander's push, m/s² (on top of the control mode).
    wander_m_per_s2: Vec3,
    /// Fleeing's push, m/s² (on top of the control mode; zero when calm).
    escape_m_per_s2: Vec3,
}

impl StepRecord {
    /// Did the fish flee a shark?
    pub(super) fn fleeing(&self) -> bool {
        self.fleeing
    }
}

/// What fish `fish` paid attention to in the last step, and what came of it
/// ([`super::world::World::attention`]). Vectors are in the tank's frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Attention {
    pub fish: usize,
    /// How the urges were combined.
    pub mode: ControlMode,
    /// The neighbours it heeded, nearest first (at most
    /// [`SteeringTuning::topological_neighbours`](crate::sim::common::steering_tuning::SteeringTuning::topological_neighbours)):
    /// the same list the step's search found.
    pub neighbours: Vec<usize>,
    /// Did it also see a distant school (the far field's pull, part of cohesion)?
    pub sees_far_school: bool,
    /// Each urge as the control mode weighs it, m/s²: what it adds to the
    /// steering when applied ([`control_mode::contributions`]: in Blended mode
    /// its weighted share, in the one-action modes its full share).
    pub urges_m_per_s2: [Vec3; 5],
    /// How much each urge was needed, 0–1 (Classic picks the largest weight ×
    /// share × need).
    pub needs: [f32; 5],
    /// The weights in use (0–100; a fleeing fish's cohesion and separation
    /// change, see [`crate::sim::boids::params::BoidWorldParams`]).
    pub weights: [f32; 5],
    /// Which urges the control mode applied in the last step.
    pub applied: [bool; 5],
    /// The applied urges together, limited to the maximum force, m/s².
    pub combined_m_per_s2: Vec3,
    /// Wander's push, on top of the control mode, m/s².
    pub wander_m_per_s2: Vec3,
    /// Fleeing from a shark, on top of the control mode, m/s² (zero when calm).
    pub escape_m_per_s2: Vec3,
    /// Did it flee a shark?
    pub fleeing: bool,
    /// The steering the step gave the fish: combined + wander + escape, m/s²
    /// (the integrator limits it to the maximum force).
    pub steering_m_per_s2: Vec3,
    /// Where it was and how it swam when it looked (the start of the step).
    pub position_m: Vec3,
    pub velocity_before_m_per_s: Vec3,
    /// How it swims after the step.
    pub velocity_m_per_s: Vec3,
}

impl Attention {
    /// The strength of each urge as weighed, m/s².
    pub fn strengths_m_per_s2(&self) -> [f32; 5] {
        self.urges_m_per_s2.map(Vec3::length)
    }

    /// The index of the urge with the largest weighed strength, if any pulls.
    pub fn strongest(&self) -> Option<usize> {
        let strengths = self.strengths_m_per_s2();
        (0..5)
            .filter(|&k| strengths[k] > 0.0)
            .max_by(|&a, &b| strengths[a].total_cmp(&strengths[b]))
    }
}

/// `shoal.state().metrics.attention`: [`Attention`] as plain numbers.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct AttentionReport {
    pub fish: usize,
    pub mode: ControlMode,
    pub neighbours: Vec<usize>,
    pub sees_far_school: bool,
    /// The five urges in [`Force::ALL`] order.
    pub urges: Vec<UrgeReport>,
    pub fleeing: bool,
    pub combined_m_per_s2: [f32; 3],
    pub wander_m_per_s2: [f32; 3],
    pub escape_m_per_s2: [f32; 3],
    pub steering_m_per_s2: [f32; 3],
    pub velocity_before_m_per_s: [f32; 3],
    pub velocity_m_per_s: [f32; 3],
}

/// One urge in [`AttentionReport`].
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct UrgeReport {
    pub urge: Force,
    /// As the control mode weighs it, m/s².
    pub vector_m_per_s2: [f32; 3],
    pub strength_m_per_s2: f32,
    pub need: f32,
    pub weight: f32,
    pub applied: bool,
}

impl From<&Attention> for AttentionReport {
    fn from(a: &Attention) -> Self {
        Self {
            fish: a.fish,
            mode: a.mode,
            neighbours: a.neighbours.clone(),
            sees_far_school: a.sees_far_school,
            urges: (0..5)
                .map(|k| UrgeReport {
                    urge: Force::ALL[k],
                    vector_m_per_s2: a.urges_m_per_s2[k].to_array(),
                    strength_m_per_s2: a.urges_m_per_s2[k].length(),
                    need: a.needs[k],
                    weight: a.weights[k],
                    applied: a.applied[k],
                })
                .collect(),
            fleeing: a.fleeing,
            combined_m_per_s2: a.combined_m_per_s2.to_array(),
            wander_m_per_s2: a.wander_m_per_s2.to_array(),
            escape_m_per_s2: a.escape_m_per_s2.to_array(),
            steering_m_per_s2: a.steering_m_per_s2.to_array(),
            velocity_before_m_per_s: a.velocity_before_m_per_s.to_array(),
            velocity_m_per_s: a.velocity_m_per_s.to_array(),
        }
    }
}

impl Attention {
    /// What fish `i` paid attention to in the last step, replayed from the
    /// step's `inputs` (the same snapshot and settings, fish `i` in `slot`),
    /// the neighbours it `heeded` (as slots), the `weights` it used and the step's `record` of it, under
    /// `mode`; `velocity_m_per_s` is how it swims after the step.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn replay(
        i: usize,
        slot: usize,
        mode: ControlMode,
        inputs: &UrgeInputs,
        heeded: &Heeded,
        weights: [f32; 5],
        record: &StepRecord,
        velocity_m_per_s: Vec3,
    ) -> Self {
        let urges = inputs.urges_of(slot, heeded);
        let urges_m_per_s2 = control_mode::contributions(mode, urges.forces(), &weights);
        let combined_m_per_s2 = control_mode::applied_sum(
            &urges_m_per_s2,
            &record.applied,
            inputs.params().max_force_m_per_s2,
        );
        Self {
            fish: i,
            mode,
            neighbours: heeded
                .neighbours()
                .iter()
                .map(|(j, _)| inputs.snapshot().fish_at_slot(j))
                .collect(),
            sees_far_school: heeded.far_centre_m().is_some(),
            urges_m_per_s2,
            needs: *urges.needs(),
            weights,
            applied: record.applied,
            combined_m_per_s2,
            wander_m_per_s2: record.wander_m_per_s2,
            escape_m_per_s2: record.escape_m_per_s2,
            fleeing: record.fleeing,
            steering_m_per_s2: combined_m_per_s2 + record.wander_m_per_s2 + record.escape_m_per_s2,
            position_m: inputs.snapshot().positions_m()[i],
            velocity_before_m_per_s: inputs.snapshot().velocities_m_per_s()[i],
            velocity_m_per_s,
        }
    }
}

/// The step's record of every fish, for the attention inspector: kept in
/// place between steps (a step allocates nothing), and withdrawn as soon as
/// anything the urges read changes.
#[derive(Clone, Debug, Default)]
pub(super) struct StepLog {
    records: Vec<StepRecord>,
    /// Can the last boid step be replayed (nothing the urges read has
    /// changed since)?
    ready: bool,
}

impl StepLog {
    /// Gets ready for a boid step of `fish_count` fish.
    pub(super) fn begin_step(&mut self, fish_count: usize) {
        self.records.resize(fish_count, StepRecord::default());
    }

    /// What fish `i` did this step: the urges the control mode `applied`,
    /// whether it was `fleeing`, and its wander and escape pushes (m/s²).
    pub(super) fn record(
        &mut self,
        i: usize,
        applied: [bool; 5],
        fleeing: bool,
        wander_m_per_s2: Vec3,
        escape_m_per_s2: Vec3,
    ) {
        self.records[i] = StepRecord {
            applied,
            fleeing,
            wander_m_per_s2,
            escape_m_per_s2,
        };
    }

    /// Ends a step: it can be replayed when it was a boid step.
    pub(super) fn end_step(&mut self, boid_step: bool) {
        self.ready = boid_step;
    }

    /// Something the urges read changed: the last step can no longer be
    /// replayed.
    pub(super) fn withdraw(&mut self) {
        self.ready = false;
    }

    /// What fish `i` did in the last boid step, while it can be replayed.
    pub(super) fn get(&self, i: usize) -> Option<&StepRecord> {
        if self.ready {
            self.records.get(i)
        } else {
            None
        }
    }
}
