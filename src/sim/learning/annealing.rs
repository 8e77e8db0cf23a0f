//! Simulated annealing of the muscle samples, Tu & Terzopoulos 1994 §4.2: "The
//! annealing algorithm repeatedly perturbs the uᵢ to modify the actuator activation
//! functions that control the muscles in the fish. It retains those perturbations
//! that produce increasingly better locomotion as measured by the objective
//! function E, and sometimes accepts those that don't to escape local minima."
//!
//! The fish starts brain-dead: every sample uniformly random in [0, 1] (seeded), no
//! warm start. One annealing step = one perturbation = one forward simulation
//! ([`crate::sim::learning::evaluate`]). A move adds Gaussian noise of standard deviation σ to 1 …
//! [`AnnealingSchedule::entries_per_move`] random samples (a time index and a
//! muscle each, clamped to [0, 1]). Metropolis rule: a move that lowers E is kept; a
//! move that raises it by ΔE is kept with probability exp(−ΔE / T).
//!
//! # Schedule
//! Over the planned K evaluations the temperature and the step size fall
//! geometrically, T(k) = T₀ (T_K / T₀)^{k/K} and σ(k) = σ₀ (σ_K / σ₀)^{k/K}, and stay at
//! their final values after K (the trainer may run on: then it is a greedy descent
//! with small steps). Defaults (chosen, see [`AnnealingSchedule::default`]):
//! T₀ = 0.005 body lengths (a move that loses 0.5 % of a body length is kept a
//! third of the time at first), T_K = 10⁻⁴, σ₀ = 0.3, σ_K = 0.05, K = 6840 (the paper's
//! longest-trained shark).
//!
//! The best controls seen so far are kept ([`Trainer::best_controls`]) and
//! snapshotted at chosen evaluation counts ([`Checkpoint`]), so one run yields the
//! sharks of the race (Fig. 7) at 90, 1440, …, 6840 steps.
//! Deterministic for a seed: ChaCha8, as elsewhere in the crate.

use crate::sim::common::fmath;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::sim::body::MUSCLE_COUNT;
use crate::sim::learning::muscle_spline::MuscleSpline;
use crate::sim::learning::objective::{Evaluation, TrainingSetup, evaluate};

/// The temperature and step schedule.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct AnnealingSchedule {
    /// K, the evaluations over which T and σ fall, count. Default 6840 (Fig. 7's
    /// best shark).
    pub planned_evaluations: u64,
    /// T₀, body lengths of objective. Default 0.005, tuned: worse moves are often
    /// kept at first (a third of those that lose 0.5 % of a body length). Measured
    /// (default setup, 2000 steps, seed 1): T₀ = 0.02 reaches E = 3.14
    /// (0.96 body lengths swum), 0.005 reaches 3.04 (1.06).
    pub initial_temperature: f32,
    /// T_K. Default 1e-4, chosen: at the end only improvements and near-ties pass.
    pub final_temperature: f32,
    /// σ₀, standard deviation of a sample's perturbation (contraction factor).
    /// Default 0.3, chosen: a third of the range, so early moves explore.
    pub initial_step: f32,
    /// σ_K. Default 0.05, chosen: fine tuning at the end.
    pub final_step: f32,
    /// Most samples perturbed by one move, count (each move perturbs 1 to this
    /// many, uniformly). Default 4, chosen.
    pub entries_per_move: usize,
    /// Probability that a perturbed sample's partner muscle (the other muscle of
    /// the same side and segment: dorsal with ventral) gets the same change, [0, 1].
    /// Default 0.5, tuned: the pair bends the body sideways together, so coupled
    /// moves learn faster (2000 steps, seed 1, T₀ = 0.02: 0.82 body lengths swum
    /// with 0, 0.96 with 0.5), while uncoupled ones still let the pair differ.
    pub paired_move_probability: f32,
}

impl Default for AnnealingSchedule {
    fn default() -> Self {
        Self {
            planned_evaluations: 6840,
            initial_temperature: 0.005,
            final_temperature: 1.0e-4,
            initial_step: 0.3,
            final_step: 0.05,
            entries_per_move: 4,
            paired_move_probability: 0.5,
        }
    }
}

impl AnnealingSchedule {
    /// Fraction of the schedule done after `k` evaluations, in [0, 1].
    fn progress(&self, k: u64) -> f32 {
        if self.planned_evaluations == 0 {
            1.0
        } else {
            (k as f64 / self.planned_evaluations as f64).min(1.0) as f32
        }
    }

    fn geometric(from: f32, to: f32, t: f32) -> f32 {
        let (a, b) = (from.max(1e-9), to.max(1e-9));
        let v = a * fmath::powf(b / a, t);
        if v.is_finite() { v } else { b }
    }

    /// T(k).
    pub fn temperature(&self, k: u64) -> f32 {
        Self::geometric(
            self.initial_temperature,
            self.final_temperature,
            self.progress(k),
        )
    }

    /// σ(k).
    pub fn step(&self, k: u64) -> f32 {
        Self::geometric(self.initial_step, self.final_step, self.progress(k))
    }
}

/// One point of the objective's history (for the learning curve).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct HistoryPoint {
    /// Annealing steps done (0 = the random start).
    pub evaluation: u64,
    /// E of the controls the annealer holds now.
    pub current_objective: f32,
    /// Lowest E so far.
    pub best_objective: f32,
    pub temperature: f32,
}

/// The best controls after a number of annealing steps.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Checkpoint {
    pub evaluations: u64,
    pub controls: MuscleSpline,
    pub objective: f32,
}

/// Incremental simulated annealing: call [`Self::run_evaluations`] a few at a time
/// (each is one forward simulation of the training interval).
#[derive(Clone, Debug)]
pub struct Trainer {
    setup: TrainingSetup,
    schedule: AnnealingSchedule,
    rng: ChaCha8Rng,
    current: MuscleSpline,
    current_objective: f32,
    best: MuscleSpline,
    best_evaluation: Evaluation,
    evaluations: u64,
    accepted: u64,
    history: Vec<HistoryPoint>,
    checkpoint_at: Vec<u64>,
    checkpoints: Vec<Checkpoint>,
}

/// A standard normal deviate (Box–Muller).
fn gaussian(rng: &mut ChaCha8Rng) -> f32 {
    let u1 = rng.random::<f32>().max(1e-7);
    let u2 = rng.random::<f32>();
    (-2.0 * fmath::ln(u1)).sqrt() * fmath::cos(std::f32::consts::TAU * u2)
}

impl Trainer {
    /// A brain-dead fish: random controls (seeded), evaluated once (step 0).
    pub fn new(setup: TrainingSetup, schedule: AnnealingSchedule, seed: u64) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut controls = MuscleSpline::constant(
            setup.sample_count,
            setup.simulated_secs(),
            setup.interpolation,
            0.0,
        );
        for i in 0..controls.sample_count() {
            for m in 0..MUSCLE_COUNT {
                controls.set_sample(i, m, rng.random::<f32>());
            }
        }
        Self::start(setup, schedule, rng, controls)
    }

    /// Starts from given controls instead of random ones (to resume a run).
    pub fn with_initial_controls(
        setup: TrainingSetup,
        schedule: AnnealingSchedule,
        seed: u64,
        controls: MuscleSpline,
    ) -> Self {
        Self::start(setup, schedule, ChaCha8Rng::seed_from_u64(seed), controls)
    }

    fn start(
        setup: TrainingSetup,
        schedule: AnnealingSchedule,
        rng: ChaCha8Rng,
        controls: MuscleSpline,
    ) -> Self {
        let evaluation = evaluate(&setup, &controls);
        let objective = evaluation.objective;
        Self {
            setup,
            schedule,
            rng,
            current: controls.clone(),
            current_objective: objective,
            best: controls,
            best_evaluation: evaluation,
            evaluations: 0,
            accepted: 0,
            history: vec![HistoryPoint {
                evaluation: 0,
                current_objective: objective,
                best_objective: objective,
                temperature: schedule.temperature(0),
            }],
            checkpoint_at: Vec::new(),
            checkpoints: Vec::new(),
        }
    }

    /// Snapshot the best controls when the step count reaches each of `counts`
    /// (a count already passed is snapshotted now with the current best).
    pub fn set_checkpoints(&mut self, counts: &[u64]) {
        self.checkpoint_at = counts.to_vec();
        self.checkpoint_at.sort_unstable();
        self.checkpoint_at.dedup();
        self.take_due_checkpoints();
    }

    fn take_due_checkpoints(&mut self) {
        while let Some(&due) = self.checkpoint_at.first() {
            if due > self.evaluations {
                break;
            }
            self.checkpoint_at.remove(0);
            self.checkpoints.push(Checkpoint {
                evaluations: due.min(self.evaluations),
                controls: self.best.clone(),
                objective: self.best_evaluation.objective,
            });
        }
    }

    /// Runs `n` annealing steps (forward simulations); returns how many ran.
    pub fn run_evaluations(&mut self, n: usize) -> usize {
        for _ in 0..n {
            self.anneal_once();
        }
        n
    }

    fn anneal_once(&mut self) {
        let k = self.evaluations;
        let sigma = self.schedule.step(k);
        let temperature = self.schedule.temperature(k);
        let mut candidate = self.current.clone();
        let samples = candidate.sample_count();
        let entries = self
            .rng
            .random_range(1..=self.schedule.entries_per_move.max(1));
        for _ in 0..entries {
            let i = self.rng.random_range(0..samples);
            let m = self.rng.random_range(0..MUSCLE_COUNT);
            let old = candidate.samples()[i][m];
            let delta = sigma * gaussian(&mut self.rng);
            candidate.set_sample(i, m, old + delta);
            if self.rng.random::<f32>() < self.schedule.paired_move_probability {
                // Muscles come in (dorsal, ventral) pairs: 2k and 2k + 1.
                let partner = m ^ 1;
                let old = candidate.samples()[i][partner];
                candidate.set_sample(i, partner, old + delta);
            }
        }
        let evaluation = evaluate(&self.setup, &candidate);
        let delta_e = evaluation.objective - self.current_objective;
        let accept =
            delta_e <= 0.0 || self.rng.random::<f32>() < fmath::exp(-delta_e / temperature);
        self.evaluations += 1;
        if accept {
            self.accepted += 1;
            self.current = candidate;
            self.current_objective = evaluation.objective;
            if evaluation.objective < self.best_evaluation.objective {
                self.best = self.current.clone();
                self.best_evaluation = evaluation;
            }
        }
        self.history.push(HistoryPoint {
            evaluation: self.evaluations,
            current_objective: self.current_objective,
            best_objective: self.best_evaluation.objective,
            temperature,
        });
        self.take_due_checkpoints();
    }

    /// The benchmark's trainer: the default setup (a 0.5 m fish swimming as far as
    /// it can in 2.5 s, 45 body steps per evaluation) and schedule, seed 1. Time
    /// `run_evaluations(n)` on it for annealing evaluations per second (the native
    /// benchmark does; the browser page can do the same).
    pub fn benchmark() -> Self {
        Self::new(TrainingSetup::default(), AnnealingSchedule::default(), 1)
    }

    pub fn setup(&self) -> &TrainingSetup {
        &self.setup
    }

    pub fn schedule(&self) -> &AnnealingSchedule {
        &self.schedule
    }

    /// Annealing steps done.
    pub fn evaluations(&self) -> u64 {
        self.evaluations
    }

    /// Accepted moves so far.
    pub fn accepted(&self) -> u64 {
        self.accepted
    }

    /// Fraction of the planned schedule done, [0, 1].
    pub fn progress(&self) -> f32 {
        self.schedule.progress(self.evaluations)
    }

    /// Has the schedule's K been reached?
    pub fn is_finished(&self) -> bool {
        self.evaluations >= self.schedule.planned_evaluations
    }

    /// Current temperature.
    pub fn temperature(&self) -> f32 {
        self.schedule.temperature(self.evaluations)
    }

    /// E after every step (one point per evaluation, the first the random start).
    pub fn history(&self) -> &[HistoryPoint] {
        &self.history
    }

    /// The lowest-E controls so far (the paper's "remembers activation patterns
    /// that improve its locomotion").
    pub fn best_controls(&self) -> &MuscleSpline {
        &self.best
    }

    /// Their evaluation, with its trajectory.
    pub fn best_evaluation(&self) -> &Evaluation {
        &self.best_evaluation
    }

    /// The controls the annealer holds now (may be worse than the best).
    pub fn current_controls(&self) -> &MuscleSpline {
        &self.current
    }

    pub fn current_objective(&self) -> f32 {
        self.current_objective
    }

    /// Snapshots taken so far, in increasing step count.
    pub fn checkpoints(&self) -> &[Checkpoint] {
        &self.checkpoints
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::body::BodyParams;
    use crate::sim::learning::annealing::*;

    pub(crate) fn cheap_setup() -> TrainingSetup {
        TrainingSetup {
            interval_secs: 1.5,
            body: BodyParams {
                jacobian_interval: 2,
                ..BodyParams::default()
            },
            ..TrainingSetup::default()
        }
    }

    #[test]
    fn schedule_falls_geometrically_and_then_holds() {
        let s = AnnealingSchedule::default();
        assert!((s.temperature(0) - s.initial_temperature).abs() < 1e-9);
        let mid = s.temperature(s.planned_evaluations / 2);
        let geometric_mean = (s.initial_temperature * s.final_temperature).sqrt();
        assert!((mid / geometric_mean - 1.0).abs() < 0.01);
        assert!((s.temperature(10 * s.planned_evaluations) - s.final_temperature).abs() < 1e-9);
        assert!(s.step(s.planned_evaluations) < s.step(0));
    }

    #[test]
    fn annealing_lowers_the_objective_well_below_the_random_start() {
        let schedule = AnnealingSchedule {
            planned_evaluations: 300,
            ..AnnealingSchedule::default()
        };
        let mut trainer = Trainer::new(cheap_setup(), schedule, 7);
        let start = trainer.history()[0].best_objective;
        trainer.set_checkpoints(&[0, 100, 300]);
        trainer.run_evaluations(300);
        let end = trainer.best_evaluation().objective;
        assert!(end < start - 0.1, "E: {start} → {end}");
        assert_eq!(trainer.history().len(), 301);
        assert!(
            trainer
                .history()
                .windows(2)
                .all(|w| w[1].best_objective <= w[0].best_objective)
        );
        let counts: Vec<u64> = trainer
            .checkpoints()
            .iter()
            .map(|c| c.evaluations)
            .collect();
        assert_eq!(counts, [0, 100, 300]);
        assert!(trainer.is_finished() && trainer.progress() == 1.0);
    }

    #[test]
    fn training_is_deterministic_for_a_seed() {
        let schedule = AnnealingSchedule {
            planned_evaluations: 20,
            ..AnnealingSchedule::default()
        };
        let run = |seed| {
            let mut t = Trainer::new(cheap_setup(), schedule, seed);
            t.run_evaluations(20);
            (t.best_controls().clone(), t.history().to_vec())
        };
        assert_eq!(run(3), run(3));
        assert_ne!(run(3).0, run(4).0);
    }
}
