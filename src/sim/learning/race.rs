//! The race of Fig. 7 (Tu & Terzopoulos 1994 §4.2): "six artificial leopard sharks
//! in a race. The furthest shark has completed only 90 annealing steps … Nearer
//! sharks have learned for progressively longer periods of time (1350 more
//! annealing steps). After learning for 6840 annealing steps, the nearest shark
//! locomotes very efficiently and it wins the race decisively."
//!
//! The entrants come from ONE annealing run snapshotted at [`PAPER_RACE_STEPS`]
//! (`Trainer::set_checkpoints`), not from six runs: a shark trained for 1440 steps
//! is then exactly the 90-step shark trained 1350 steps more, as in the paper's
//! wording, and the race costs one training instead of six. Each shark plays its
//! learned controls from rest, side by side in lanes two body lengths apart (the
//! bodies do not touch each other), looping them if the race is longer than the
//! training interval; after a fixed time the distance along the starting heading
//! decides.

use glam::Vec3;

use crate::sim::body::physical_fish::BodySpecies;
use crate::sim::body::{BodyParams, FishBody, PectoralFins};
use crate::sim::learning::annealing::Checkpoint;
use crate::sim::learning::muscle_spline::MuscleSpline;

/// Annealing steps of the six sharks of Fig. 7: 90, then 1350 more each.
pub const PAPER_RACE_STEPS: [u64; 6] = [90, 1440, 2790, 4140, 5490, 6840];

/// One shark and what it learned.
#[derive(Clone, Debug, PartialEq)]
pub struct RaceEntrant {
    pub annealing_steps: u64,
    pub controls: MuscleSpline,
}

impl RaceEntrant {
    /// One entrant per checkpoint.
    pub fn from_checkpoints(checkpoints: &[Checkpoint]) -> Vec<Self> {
        checkpoints
            .iter()
            .map(|c| Self {
                annealing_steps: c.evaluations,
                controls: c.controls.clone(),
            })
            .collect()
    }
}

#[derive(Clone, Debug)]
struct Lane {
    entrant: RaceEntrant,
    body: FishBody,
    start_m: Vec3,
}

/// A race in progress; step it for an animation or [`Self::run`] it.
#[derive(Clone, Debug)]
pub struct Race {
    lanes: Vec<Lane>,
    steps: u64,
    dt_secs: f32,
}

impl Race {
    /// Entrants side by side at the start line (x = 0), lane k at
    /// y = 2k body lengths, all heading +x (body frame, z up), at rest.
    pub fn new(entrants: Vec<RaceEntrant>, species: BodySpecies, params: BodyParams) -> Self {
        let length_m = species.body_length_m();
        let lanes: Vec<Lane> = entrants
            .into_iter()
            .enumerate()
            .map(|(k, entrant)| {
                let start = Vec3::new(0.0, 2.0 * length_m * k as f32, 0.0);
                let body = FishBody::with_params(length_m, start, Vec3::X, params);
                Lane {
                    start_m: body.centre_of_mass_m(),
                    entrant,
                    body,
                }
            })
            .collect();
        Self {
            lanes,
            steps: 0,
            dt_secs: params.dt_secs,
        }
    }

    /// One body step for every shark.
    pub fn step(&mut self) {
        self.steps += 1;
        let t = self.time_secs();
        for lane in &mut self.lanes {
            // The first lap exactly as in training (its last step included), then
            // looped.
            let period = lane.entrant.controls.duration_secs();
            let local = |t: f32| if t <= period { t } else { t.rem_euclid(period) };
            let controls = &lane.entrant.controls;
            let step_start_secs = t - self.dt_secs;
            lane.body
                .step_with(&PectoralFins::NEUTRAL, Vec3::ZERO, |s| {
                    controls.value_at(local(step_start_secs + s))
                });
        }
    }

    /// Runs until `secs` have passed since the start (to the nearest step).
    pub fn run(&mut self, secs: f32) {
        while self.time_secs() + 0.5 * self.dt_secs < secs {
            self.step();
        }
    }

    /// Time since the start, seconds.
    pub fn time_secs(&self) -> f32 {
        self.steps as f32 * self.dt_secs
    }

    /// Distance of each shark's centre of mass along the starting heading, metres
    /// (entrants' order).
    pub fn distances_m(&self) -> Vec<f32> {
        self.lanes
            .iter()
            .map(|l| l.body.centre_of_mass_m().x - l.start_m.x)
            .collect()
    }

    /// The entrants in lane order.
    pub fn entrants(&self) -> impl Iterator<Item = &RaceEntrant> {
        self.lanes.iter().map(|l| &l.entrant)
    }

    /// The bodies in lane order (body frame, z up), for drawing.
    pub fn bodies(&self) -> impl Iterator<Item = &FishBody> {
        self.lanes.iter().map(|l| &l.body)
    }

    /// Lane of the shark in front, if any.
    pub fn leader(&self) -> Option<usize> {
        self.distances_m()
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))
            .map(|(k, _)| k)
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::learning::annealing::{AnnealingSchedule, Trainer};
    use crate::sim::learning::objective::TrainingSetup;
    use crate::sim::learning::race::*;

    #[test]
    fn sharks_trained_longer_race_farther() {
        let setup = TrainingSetup {
            species: BodySpecies::Shark,
            interval_secs: 1.5,
            body: BodyParams {
                jacobian_interval: 2,
                ..BodyParams::default()
            },
            ..TrainingSetup::default()
        };
        // The paper's 90 + 1350 k steps, scaled down for a test.
        let steps = [10, 60, 160, 300];
        let schedule = AnnealingSchedule {
            planned_evaluations: 300,
            ..AnnealingSchedule::default()
        };
        let mut trainer = Trainer::new(setup, schedule, 11);
        trainer.set_checkpoints(&steps);
        trainer.run_evaluations(300);
        let entrants = RaceEntrant::from_checkpoints(trainer.checkpoints());
        assert_eq!(
            entrants
                .iter()
                .map(|e| e.annealing_steps)
                .collect::<Vec<_>>(),
            steps
        );
        let mut race = Race::new(entrants, BodySpecies::Shark, setup.body);
        race.run(setup.simulated_secs());
        let d = race.distances_m();
        assert!(
            d.windows(2).all(|w| w[1] >= w[0] - 1e-4),
            "distances {d:?} m"
        );
        let length_m = BodySpecies::Shark.body_length_m();
        assert!(d[3] > d[0] + 0.1 * length_m, "distances {d:?} m");
        assert_eq!(race.leader(), Some(3));
        // Over the training interval the race replays training exactly.
        let trained = trainer.best_evaluation().forward_body_lengths * length_m;
        assert!((d[3] - trained).abs() < 1e-3, "{} m vs {trained} m", d[3]);
        assert!(
            race.bodies()
                .all(|b| b.positions_m().iter().all(|p| p.is_finite()))
        );
    }
}
