//! The learning lab's part of `shoal.state()`: training progress, the
//! controllers in use, the buoys and the race.

use serde::Serialize;

use super::learning_lab::LearningLab;

/// The learning lab as `shoal.state().learning` reports it.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct LearningReport {
    /// The drill in training (0-based), `null` when all are learned.
    pub drill: Option<usize>,
    pub drills: usize,
    /// Whole training, 0–1.
    pub progress: f32,
    /// Annealing steps done in the current drill.
    pub evaluations: u64,
    pub annealing_steps: u64,
    /// E of the best and of the current controls of the current drill.
    pub best_objective: f32,
    pub current_objective: f32,
    /// E at the random start of the current drill.
    pub start_objective: f32,
    /// Drills learned: their objective and the energy kept by two modes.
    pub finished: Vec<(f32, f32)>,
    /// `"shipped"`, `"trained_here"` or `"loaded"`.
    pub source: crate::sim::learning::learning_lab::SetSource,
    pub controller: crate::sim::learning::learning_lab::ControllerChoice,
    /// Seconds at which the swimmer reached a buoy.
    pub buoy_times_secs: Vec<f32>,
    /// The race: annealing steps and distance of each shark.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub race: Option<Vec<(u64, f32)>>,
    /// Entrants ready for a race.
    pub race_entrants: usize,
}

impl LearningLab {
    /// What `shoal.state().learning` reports.
    pub fn report(&self) -> LearningReport {
        let l = self;
        let t = l.trainer();
        let (_, source) = l.learned_set();
        LearningReport {
            drill: l.current_drill(),
            drills: l.drills().len(),
            progress: l.progress(),
            evaluations: t.evaluations(),
            annealing_steps: l.annealing_steps(),
            best_objective: t.best_evaluation().objective,
            current_objective: t.current_objective(),
            start_objective: t
                .history()
                .first()
                .map_or(t.current_objective(), |h| h.current_objective),
            finished: (0..l.finished_drills().len())
                .map(|k| {
                    (
                        l.finished_drills()[k].objective,
                        l.abstraction(k)
                            .map_or(0.0, |a| a.controller.energy_fraction),
                    )
                })
                .collect(),
            source,
            controller: l.controller(),
            buoy_times_secs: l.buoy_times_secs(),
            race: l.race().map(|r| {
                r.entrants()
                    .map(|e| e.annealing_steps)
                    .zip(r.distances_m())
                    .collect()
            }),
            race_entrants: l.race_entrants().len(),
        }
    }
}
