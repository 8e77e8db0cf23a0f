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
    /// step's `inputs` (the same snapshot and settings), the neighbours it
    /// `heeded`, the `weights` it used and the step's `record` of it, under
    /// `mode`; `velocity_m_per_s` is how it swims after the step.
    pub(super) fn replay(
        i: usize,
        mode: ControlMode,
        inputs: &UrgeInputs,
        heeded: &Heeded,
        weights: [f32; 5],
        record: &StepRecord,
        velocity_m_per_s: Vec3,
    ) -> Self {
        let urges = inputs.urges_of(i, heeded);
        let urges_m_per_s2 = control_mode::contributions(mode, urges.forces(), &weights);
        let combined_m_per_s2 = control_mode::applied_sum(
            &urges_m_per_s2,
            &record.applied,
            inputs.params().max_force_m_per_s2,
        );
        Self {
            fish: i,
            mode,
            neighbours: heeded.neighbours().iter().map(|(j, _)| j).collect(),
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

#[cfg(test)]
mod tests {
    use glam::Vec3;

    use super::*;
    use crate::sim::boids::forces;
    use crate::sim::boids::urges::boid_steering_params;
    use crate::sim::boids::world::{BoidParams, DT_SECS, World, WorldConfig};
    use crate::sim::common::spatial_grid::SpatialGrid;
    use crate::sim::common::steering;

    /// A schooling tank (Table 1's group weights in `mode`), stepped `steps` times.
    fn school(mode: ControlMode, sharks: usize, steps: usize) -> World {
        let mut w = World::new(WorldConfig {
            seed: 5,
            fish_count: 120,
            sharks,
            ..WorldConfig::default()
        });
        w.set_boids(Some(BoidParams {
            mode,
            ..BoidParams::group()
        }));
        for _ in 0..steps {
            w.step();
        }
        w
    }

    #[test]
    fn the_heeded_neighbours_are_the_steps_search() {
        let mut w = school(ControlMode::Blended, 0, 0);
        assert_eq!(w.attention(0), None, "no step yet: nothing to report");
        let before = w.clone();
        // The first boid step searches every fish's neighbours from scratch.
        w.step();
        let positions: Vec<Vec3> = before.fish().iter().map(|f| f.position_m).collect();
        let velocities: Vec<Vec3> = before.fish().iter().map(|f| f.velocity_m_per_s).collect();
        let mut grid = SpatialGrid::default();
        let tank = before.tank();
        grid.rebuild(tank.min_m, tank.max_m, 0.5, &positions);
        let boids = *w.boids().unwrap();
        let tuning = w.world_params().steering;
        let mut links = Vec::new();
        let mut heeding = 0;
        for i in 0..w.fish().len() {
            let attention = w.attention(i).unwrap();
            let mut searched: Vec<usize> = forces::heeded_neighbours(
                &positions,
                &velocities,
                i,
                &grid,
                &boids.perception,
                &tuning,
            )
            .iter()
            .map(|(j, _)| j)
            .collect();
            let mut heeded = attention.neighbours.clone();
            w.interaction_neighbours(i, &mut links);
            assert_eq!(heeded, links, "fish {i}: the vision links' list");
            assert!(heeded.len() <= tuning.topological_neighbours);
            searched.sort_unstable();
            heeded.sort_unstable();
            assert_eq!(heeded, searched, "fish {i}");
            heeding += usize::from(!heeded.is_empty());
        }
        assert!(heeding > 100, "most fish heed someone: {heeding}");
        // Later steps recheck the lists in between searches; still the step's own.
        for _ in 0..7 {
            w.step();
        }
        for i in 0..w.fish().len() {
            w.interaction_neighbours(i, &mut links);
            assert_eq!(w.attention(i).unwrap().neighbours, links);
        }
    }

    /// Replays the last step's integration of every fish from the reported
    /// steering and compares with where the step left it: the reported urges,
    /// combined by the mode's rule, are the steering the fish felt.
    fn assert_urges_explain_the_velocity_change(mode: ControlMode, sharks: usize) {
        let mut w = school(mode, sharks, 30);
        let before = w.clone();
        w.step();
        let boids = *w.boids().unwrap();
        let params = boid_steering_params(w.params(), &boids.perception);
        let mut checked = 0;
        for i in 0..w.fish().len() {
            let a = w.attention(i).unwrap();
            assert_eq!(a.velocity_before_m_per_s, before.fish()[i].velocity_m_per_s);
            // The mode's rule: the applied urges' sum, limited.
            let sum: Vec3 = (0..5)
                .filter(|&k| a.applied[k])
                .map(|k| a.urges_m_per_s2[k])
                .sum();
            let combined = steering::limit(sum, boids.perception.max_force_m_per_s2);
            assert_eq!(a.combined_m_per_s2, combined);
            assert_eq!(
                a.steering_m_per_s2,
                combined + a.wander_m_per_s2 + a.escape_m_per_s2
            );
            let mut replay = before.fish()[i];
            replay.integrate(a.steering_m_per_s2, &params, DT_SECS);
            let after = w.fish()[i];
            // Skip fish the hard rules touched (at the glass or a rock).
            if replay.position_m.distance(after.position_m) > 1e-6 {
                continue;
            }
            assert!(
                replay.velocity_m_per_s.distance(a.velocity_m_per_s) < 1e-6,
                "{mode:?} fish {i}: replayed {} against {}",
                replay.velocity_m_per_s,
                a.velocity_m_per_s
            );
            checked += 1;
        }
        assert!(checked > 100, "{mode:?}: only {checked} fish checked");
    }

    #[test]
    fn the_reported_urges_are_the_steering_of_the_step_in_every_mode() {
        for mode in ControlMode::ALL {
            assert_urges_explain_the_velocity_change(mode, 0);
        }
        assert_urges_explain_the_velocity_change(ControlMode::Blended, 2);
    }

    #[test]
    fn each_mode_marks_the_urges_its_rule_applies() {
        for mode in ControlMode::ALL {
            let w = school(mode, 0, 20);
            let mut counts = [0usize; 6];
            for i in 0..w.fish().len() {
                let a = w.attention(i).unwrap();
                let applied = a.applied.iter().filter(|&&x| x).count();
                counts[applied] += 1;
                match mode {
                    // Every urge with a weight, every step.
                    ControlMode::Blended => assert_eq!(a.applied, [true; 5]),
                    // The most pressing urge alone (none when nothing pulls).
                    ControlMode::Classic => {
                        assert!(applied <= 1);
                        let pulls = a.urges_m_per_s2.iter().any(|u| *u != Vec3::ZERO);
                        assert_eq!(applied == 1, pulls, "fish {i}");
                    }
                    // One ticket drawn.
                    ControlMode::MonteCarlo => assert_eq!(applied, 1),
                    // Each urge whose weight beat the one dice roll: a lighter
                    // urge is applied only with every heavier one.
                    ControlMode::DirectAlternate => {
                        for k in 0..5 {
                            for m in 0..5 {
                                if a.applied[k] && a.weights[m] > a.weights[k] {
                                    assert!(a.applied[m], "fish {i}: {k} without {m}");
                                }
                            }
                        }
                    }
                }
            }
            assert!(counts.iter().sum::<usize>() == w.fish().len(), "{counts:?}");
        }
    }

    #[test]
    fn asking_changes_nothing_and_a_change_of_the_school_withdraws_the_report() {
        let mut asked = school(ControlMode::MonteCarlo, 1, 10);
        let mut plain = asked.clone();
        for _ in 0..20 {
            for i in 0..asked.fish().len() {
                assert!(asked.attention(i).is_some());
            }
            asked.step();
            plain.step();
        }
        for (a, b) in asked.fish().iter().zip(plain.fish()) {
            assert_eq!(a.position_m, b.position_m);
            assert_eq!(a.velocity_m_per_s, b.velocity_m_per_s);
        }
        assert!(asked.attention(119).is_some());
        assert_eq!(asked.attention(120), None, "no such fish");
        asked.set_fish_count(50);
        assert_eq!(asked.attention(10), None, "until the next step");
        asked.step();
        assert!(asked.attention(10).is_some());
        assert_eq!(asked.attention(60), None);
        asked.set_obstacles(Vec::new());
        assert_eq!(asked.attention(10), None, "the rocks changed");
        asked.set_boids(None);
        asked.step();
        assert_eq!(asked.attention(10), None, "wandering fish have no urges");
    }
}
