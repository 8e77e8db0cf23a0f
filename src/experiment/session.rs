//! An experiment run inside the app, a slice per frame (issue 16).
//!
//! The browser has one thread: an experiment that ran to its end in one go
//! would freeze the page. [`ExperimentSession::slice`] spends about a given
//! wall time per frame (the app gives it [`FRAME_BUDGET_SECS`]), choosing the
//! number of steps from the measured cost of a step, so the tank keeps being
//! drawn while the runs go on. The slices never change the runs: a run stepped
//! a few steps per frame gives the same CSV as one run to its end
//! (see the tests).

use serde::Serialize;

use crate::experiment::{Experiment, ExperimentProgress, Plan, SummaryRow};

/// Wall seconds of a frame given to the experiment. Default 15 ms: with the
/// tank's own steps and the drawing, a frame stays under about 33 ms (30 frames
/// a second) on a laptop.
pub const FRAME_BUDGET_SECS: f64 = 0.015;

/// Share of the page's own frame time (drawing, the tank, the UI) given to the
/// runs when that is slower than [`FRAME_BUDGET_SECS`] / this share. Default
/// 0.5: on a slow computer (or a software renderer) whose page already draws
/// under 30 frames a second, the runs take half as long again as a frame
/// (the page then draws at two thirds of its rate) instead of a sliver of it,
/// so a class's experiment does not crawl; on a laptop with a GPU the runs
/// keep their 15 ms.
pub const SLOW_FRAME_SHARE: f64 = 0.5;

/// Most wall seconds of a frame given to the runs, however slow the page.
/// Default 0.25 s: the page still answers within a quarter of a second more.
pub const MAX_FRAME_BUDGET_SECS: f64 = 0.25;

/// This frame's slice for background runs, from the page's own time in the
/// last frame (its interval less the runs' slice): [`FRAME_BUDGET_SECS`], or
/// [`SLOW_FRAME_SHARE`] of a slow page's own time, at most
/// [`MAX_FRAME_BUDGET_SECS`].
pub fn frame_budget_secs(own_frame_secs: f64) -> f64 {
    if own_frame_secs.is_finite() {
        (own_frame_secs * SLOW_FRAME_SHARE).clamp(FRAME_BUDGET_SECS, MAX_FRAME_BUDGET_SECS)
    } else {
        FRAME_BUDGET_SECS
    }
}

/// Most steps in one slice, whatever the measured cost (a guard against a cost
/// measured as zero on a coarse clock).
const MAX_STEPS_PER_SLICE: u64 = 100_000;

/// `shoal.state().experiment`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ExperimentReport {
    pub name: String,
    /// Runs are still to be done and the experiment was not cancelled.
    pub running: bool,
    pub paused: bool,
    /// Cancelled: the completed runs' results are kept.
    pub cancelled: bool,
    pub runs_done: usize,
    pub runs_total: usize,
    pub steps_done: u64,
    pub steps_total: u64,
    /// Once finished (or cancelled): the summary of the completed runs.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub summary: Option<Vec<SummaryRow>>,
    /// Once finished (or cancelled): the CSV of the completed runs.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub csv: Option<String>,
}

/// Steps that fit in `budget_secs` at `secs_per_step` (at least one).
pub fn steps_for_budget(budget_secs: f64, secs_per_step: f64) -> u64 {
    if secs_per_step > 0.0 && secs_per_step.is_finite() {
        ((budget_secs / secs_per_step).floor() as u64).clamp(1, MAX_STEPS_PER_SLICE)
    } else {
        1
    }
}

/// An experiment in the app: its progress, pause and cancel, and the measured
/// cost of its steps.
pub struct ExperimentSession {
    experiment: Experiment,
    paused: bool,
    cancelled: bool,
    /// Wall seconds per step, measured (smoothed); before the first slice, the
    /// engine's estimate.
    secs_per_step: f64,
    /// Wall seconds the experiment has been under way (not paused), frames
    /// included: what "time left" extrapolates.
    running_wall_secs: f64,
    last_frame_secs: Option<f64>,
}

impl ExperimentSession {
    /// Starts every run of `plan`; `guess_secs_per_step` seeds the first slice.
    pub fn new(plan: Plan, guess_secs_per_step: f64) -> Self {
        Self {
            experiment: Experiment::new(plan),
            paused: false,
            cancelled: false,
            secs_per_step: guess_secs_per_step,
            running_wall_secs: 0.0,
            last_frame_secs: None,
        }
    }

    pub fn plan(&self) -> &Plan {
        self.experiment.plan()
    }

    pub fn experiment(&self) -> &Experiment {
        &self.experiment
    }

    pub fn progress(&self) -> ExperimentProgress {
        self.experiment.progress()
    }

    /// Runs remain, not cancelled.
    pub fn running(&self) -> bool {
        !self.cancelled && !self.experiment.progress().done
    }

    pub fn paused(&self) -> bool {
        self.paused
    }

    pub fn cancelled(&self) -> bool {
        self.cancelled
    }

    pub fn set_paused(&mut self, paused: bool) {
        self.paused = paused;
        self.last_frame_secs = None;
    }

    /// Stops for good; the completed runs' results stay.
    pub fn cancel(&mut self) {
        self.cancelled = true;
    }

    /// Measured wall seconds per step.
    pub fn secs_per_step(&self) -> f64 {
        self.secs_per_step
    }

    /// One frame's slice: about `budget_secs` of steps, unless paused, done or
    /// cancelled. `now_secs` is the frame's wall time (for "time left").
    pub fn slice(&mut self, budget_secs: f64, now_secs: f64) -> ExperimentProgress {
        if !self.running() || self.paused {
            self.last_frame_secs = None;
            return self.progress();
        }
        if let Some(last) = self.last_frame_secs {
            // A hidden tab's long gap does not count.
            self.running_wall_secs += (now_secs - last).clamp(0.0, 0.25);
        }
        self.last_frame_secs = Some(now_secs);
        let steps = steps_for_budget(budget_secs, self.secs_per_step);
        let before = self.progress().steps_done;
        let started = web_time::Instant::now();
        let progress = self.experiment.advance(steps);
        let taken = progress.steps_done - before;
        if taken > 0 {
            let cost = started.elapsed().as_secs_f64() / taken as f64;
            self.secs_per_step = if self.secs_per_step > 0.0 {
                0.7 * self.secs_per_step + 0.3 * cost
            } else {
                cost
            };
        }
        progress
    }

    /// Steps exactly `steps` (tests, and `shoal-lab`-like callers).
    pub fn advance(&mut self, steps: u64) -> ExperimentProgress {
        self.experiment.advance(steps)
    }

    /// Wall seconds left at the rate seen so far (`None` before it is known).
    pub fn secs_left(&self) -> Option<f64> {
        let p = self.progress();
        if p.steps_done == 0 || self.running_wall_secs < 0.5 {
            return None;
        }
        let rate = p.steps_done as f64 / self.running_wall_secs;
        Some((p.steps_total - p.steps_done) as f64 / rate)
    }

    /// What `shoal.state().experiment` says; the summary and the CSV once the
    /// experiment is over (finished or cancelled).
    pub fn report(&self) -> ExperimentReport {
        let p = self.progress();
        let over = !self.running();
        ExperimentReport {
            name: self.plan().design.name.clone(),
            running: self.running(),
            paused: self.paused,
            cancelled: self.cancelled,
            runs_done: p.runs_done,
            runs_total: p.runs_total,
            steps_done: p.steps_done,
            steps_total: p.steps_total,
            summary: over.then(|| self.experiment.summary()),
            csv: over.then(|| self.experiment.csv()),
        }
    }
}
