//! Running an experiment's runs, in slices.
//!
//! A run is the interactive run of the same settings and seed: a
//! [`Lab`] built by [`Lab::new`] and advanced by [`Lab::step`], measured at the
//! lab's own metrics samples (every 0.25 s in the boid scenes, 0.275 s in the
//! others) from the same [`crate::metrics_history::MetricsSample`] and reef
//! census the plots and the CSV export read. So a result can be reproduced by
//! opening the run's settings link, setting the seed and watching.
//!
//! [`ExperimentRun::advance`] runs at most a given number of steps and returns,
//! so the browser can spend a few milliseconds per frame on an experiment and
//! stay responsive; the stop points never change the run (the lab's steps are
//! the same whether taken one by one or a thousand at a time).

use serde_json::Value;

use crate::experiment::design::{Measure, Plan, RunSpec};
use crate::lab::Lab;

/// What one run measured: the samples of its measuring window.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct RunResult {
    pub index: usize,
    pub seed: u64,
    /// The run's factor levels, in the design's order.
    pub levels: Vec<Value>,
    /// Simulated time of each sample in the window, seconds since the run began.
    pub times_secs: Vec<f64>,
    /// Per measure of the plan (in its order), one value per sample.
    pub values: Vec<Vec<f64>>,
}

impl RunResult {
    /// The mean over the window of measure `m` (the plan's `m`-th).
    pub fn mean(&self, m: usize) -> f64 {
        let v = &self.values[m];
        if v.is_empty() {
            f64::NAN
        } else {
            v.iter().sum::<f64>() / v.len() as f64
        }
    }

    /// The last sample of measure `m`.
    pub fn last(&self, m: usize) -> f64 {
        self.values[m].last().copied().unwrap_or(f64::NAN)
    }
}

/// How far a run is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct RunProgress {
    pub steps_done: u64,
    pub steps_total: u64,
    pub done: bool,
}

/// One run in progress.
pub struct ExperimentRun {
    spec: RunSpec,
    lab: Lab,
    measures: Vec<Measure>,
    warmup_steps: u64,
    total_steps: u64,
    sample_every_steps: u64,
    /// The counters at the end of the warm-up (see [`Measure::is_counter`]).
    baseline: Vec<f64>,
    /// Does the plan measure the distance swum? Then the measuring window is
    /// stepped one step at a time, adding up the fish's mean speed.
    tracks_distance: bool,
    /// The distance the average fish swam since the window began (metres).
    distance_swum_m: f64,
    times_secs: Vec<f64>,
    values: Vec<Vec<f64>>,
}

impl ExperimentRun {
    /// Run `spec` of `plan`, at step 0.
    pub fn new(plan: &Plan, spec: &RunSpec) -> Self {
        let measures: Vec<Measure> = plan.measures.iter().map(|&(m, _)| m).collect();
        let lab = Lab::new(plan.settings_for(spec));
        let mut run = Self {
            tracks_distance: measures.contains(&Measure::DistanceSwum),
            distance_swum_m: 0.0,
            spec: spec.clone(),
            values: vec![Vec::new(); measures.len()],
            measures,
            lab,
            warmup_steps: plan.warmup_steps,
            total_steps: plan.steps_per_run(),
            sample_every_steps: plan.sample_every_steps,
            baseline: Vec::new(),
            times_secs: Vec::new(),
        };
        if run.warmup_steps == 0 {
            run.baseline = run.read_now();
        }
        run
    }

    /// The lab this run steps (for a test, or a panel that shows it).
    pub fn lab(&self) -> &Lab {
        &self.lab
    }

    pub fn spec(&self) -> &RunSpec {
        &self.spec
    }

    pub fn progress(&self) -> RunProgress {
        let steps_done = self.lab.runs()[0].steps();
        RunProgress {
            steps_done,
            steps_total: self.total_steps,
            done: steps_done >= self.total_steps,
        }
    }

    /// Runs at most `max_steps` more steps (fewer at the end) and reports.
    pub fn advance(&mut self, max_steps: u64) -> RunProgress {
        let every = self.sample_every_steps;
        let mut budget = max_steps;
        let mut steps = self.lab.runs()[0].steps();
        while budget > 0 && steps < self.total_steps {
            // Stop at the next sample, the end of the warm-up, or the end.
            let mut stop = ((steps / every + 1) * every).min(self.total_steps);
            if steps < self.warmup_steps {
                stop = stop.min(self.warmup_steps);
            }
            let mut n = (stop - steps).min(budget);
            let measuring = steps >= self.warmup_steps;
            if self.tracks_distance && measuring {
                n = 1;
            }
            self.lab.step(n as u32);
            budget -= n;
            steps = self.lab.runs()[0].steps();
            if self.tracks_distance && measuring {
                let scene = self.lab.runs()[0].scene();
                let speed = scene.school_mean_speed_m_per_s();
                self.distance_swum_m += speed.unwrap_or(0.0) * scene.dt_secs();
            }
            if steps == self.warmup_steps {
                self.baseline = self.read_now();
            }
            if steps > self.warmup_steps && steps.is_multiple_of(every) {
                self.record_sample();
            }
        }
        self.progress()
    }

    /// Runs to the end and returns the result.
    pub fn run_to_end(mut self) -> RunResult {
        self.advance(u64::MAX);
        self.finish()
    }

    /// The result (of the samples taken so far, if not done).
    pub fn finish(self) -> RunResult {
        RunResult {
            index: self.spec.index,
            seed: self.spec.seed,
            levels: self.spec.levels,
            times_secs: self.times_secs,
            values: self.values,
        }
    }

    /// The lab's latest sample (taken at this step), counters from the window's
    /// start.
    fn record_sample(&mut self) {
        let run = &self.lab.runs()[0];
        let sample = run.metrics();
        let census = run.census().back().copied();
        self.times_secs.push(sample.time_secs);
        for (k, &measure) in self.measures.iter().enumerate() {
            let value = match measure_value(measure, &sample, census.as_ref()) {
                Some(v) if measure.is_counter() => v - self.baseline.get(k).copied().unwrap_or(0.0),
                Some(v) => v,
                // Added up step by step since the window began.
                None => self.distance_swum_m,
            };
            self.values[k].push(value);
        }
    }

    /// Every measure's value now, from what a sample would read.
    fn read_now(&self) -> Vec<f64> {
        let scene = self.lab.runs()[0].scene();
        let metrics = scene.metrics();
        let sample = metrics.map_or_else(Default::default, |m| {
            crate::metrics_history::MetricsSample::new(
                m.time_secs,
                &m.school,
                m.force_frequencies,
                m.catches,
            )
        });
        let census = scene.census();
        self.measures
            .iter()
            .map(|&m| measure_value(m, &sample, census.as_ref()).unwrap_or(0.0))
            .collect()
    }
}

/// One measure of a metrics sample and the reef's census at the same step;
/// `None` for [`Measure::DistanceSwum`], which is not in a sample (a run adds
/// it up step by step).
pub fn measure_value(
    measure: Measure,
    sample: &crate::metrics_history::MetricsSample,
    census: Option<&crate::sim::reef::report::ReefCensus>,
) -> Option<f64> {
    let counts = census.map(|c| c.counts).unwrap_or_default();
    Some(match measure {
        Measure::Polarization => f64::from(sample.polarization),
        Measure::Milling => f64::from(sample.milling),
        Measure::NndBodyLengths => f64::from(sample.nnd_body_lengths),
        Measure::Groups => f64::from(sample.groups),
        Measure::MeanSpeed => f64::from(sample.mean_speed),
        Measure::Catches => sample.catches as f64,
        Measure::FoodEaten => f64::from(counts.food_eaten),
        Measure::Spawnings => f64::from(counts.spawnings),
        Measure::MissedStrikes => f64::from(counts.missed_strikes),
        Measure::FishCollisions => f64::from(counts.fish_collisions),
        Measure::PreyAlive => census.map_or(0.0, |c| c.prey as f64),
        Measure::DistanceSwum => return None,
    })
}

/// How far an experiment is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct ExperimentProgress {
    pub runs_done: usize,
    pub runs_total: usize,
    /// Steps of every run together (the progress bar's measure).
    pub steps_done: u64,
    pub steps_total: u64,
    pub done: bool,
}

/// A plan's runs (or a shard's) one after another, in slices: what the browser
/// drives frame by frame. Cancelling is dropping it after taking
/// [`Self::results`], the completed runs.
pub struct Experiment {
    plan: Plan,
    runs: Vec<RunSpec>,
    next: usize,
    current: Option<ExperimentRun>,
    results: Vec<RunResult>,
}

impl Experiment {
    /// Every run of `plan`.
    pub fn new(plan: Plan) -> Self {
        let runs = plan.runs();
        Self::with_runs(plan, runs)
    }

    /// The given runs of `plan` (a shard).
    pub fn with_runs(plan: Plan, runs: Vec<RunSpec>) -> Self {
        Self {
            plan,
            runs,
            next: 0,
            current: None,
            results: Vec::new(),
        }
    }

    pub fn plan(&self) -> &Plan {
        &self.plan
    }

    /// The completed runs, in run order.
    pub fn results(&self) -> &[RunResult] {
        &self.results
    }

    /// Runs at most `max_steps` steps, across runs, and reports.
    pub fn advance(&mut self, max_steps: u64) -> ExperimentProgress {
        let mut budget = max_steps;
        while budget > 0 {
            if self.current.is_none() {
                let Some(spec) = self.runs.get(self.next) else {
                    break;
                };
                self.current = Some(ExperimentRun::new(&self.plan, spec));
                self.next += 1;
            }
            let Some(run) = self.current.as_mut() else {
                break;
            };
            let before = run.progress().steps_done;
            let progress = run.advance(budget);
            budget -= progress.steps_done - before;
            if progress.done
                && let Some(run) = self.current.take()
            {
                self.results.push(run.finish());
            }
        }
        self.progress()
    }

    pub fn progress(&self) -> ExperimentProgress {
        let per_run = self.plan.steps_per_run();
        let current = self.current.as_ref().map_or(0, |r| r.progress().steps_done);
        let runs_done = self.results.len();
        ExperimentProgress {
            runs_done,
            runs_total: self.runs.len(),
            steps_done: runs_done as u64 * per_run + current,
            steps_total: self.runs.len() as u64 * per_run,
            done: runs_done == self.runs.len(),
        }
    }

    /// The CSV of the completed runs (all of them once done; see
    /// [`crate::experiment::csv::experiment_csv`]).
    pub fn csv(&self) -> String {
        crate::experiment::csv::experiment_csv(&self.plan, &self.results, None)
    }

    /// Mean and 95 % interval over seeds per level, of the completed runs.
    pub fn summary(&self) -> Vec<crate::experiment::summary::SummaryRow> {
        crate::experiment::summary::summarise(&self.plan, &self.results)
    }
}
