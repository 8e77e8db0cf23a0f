//! Experiments (issue 16): sweeps over one or two settings and over seeds, with
//! the school's measures summarised per run, in the browser and headless.
//!
//! The pieces, in the order an experiment uses them:
//!
//! - [`design`]: the experiment file ([`Design`], serde) and its validation into a
//!   [`Plan`] (the base settings, each factor's levels, the seeds, the measures,
//!   the step counts), with a [`DesignError`] naming the field for everything a
//!   design can get wrong; the runs in their fixed order ([`RunSpec`]) and the
//!   shards of a cluster job ([`Plan::runs_for_shard`]).
//! - [`runner`]: one run ([`ExperimentRun`]) is exactly the interactive run of
//!   the same settings and seed (a [`crate::lab::Lab`] stepped by
//!   [`crate::lab::Lab::step`], measured from the same metrics samples and reef
//!   census the plots read), advanced in slices so that the browser can
//!   time-slice it; [`Experiment`] runs a plan's runs one after another.
//! - [`session`]: an experiment inside the app, a slice of wall time per
//!   frame, with pause, cancel and `shoal.state().experiment`.
//! - [`csv`]: the tidy CSV (one row per run × measure, × sample for series), its
//!   `#` lines carrying the design, and the merge of shard files.
//! - [`summary`]: mean and 95 % confidence interval over seeds per level, for the
//!   dose–response plot.
//!
//! Pure and single-threaded (no threads, no clock, no files): the same code runs
//! in wasm; `src/bin/shoal-lab.rs` adds the cores, the progress bar and the files.
//! File format and commands: `docs/experiments.md`.

pub mod csv;
pub mod design;
pub mod link;
pub mod measure;
pub mod runner;
pub mod session;
pub mod summary;

pub use self::csv::{MergeError, experiment_csv, merge_csv};
pub use self::design::{Design, DesignError, Estimate, Measure, Plan, RunSpec, Summary};
pub use self::runner::{Experiment, ExperimentProgress, ExperimentRun, RunProgress, RunResult};
pub use self::session::{ExperimentReport, ExperimentSession};
pub use self::summary::{SummaryRow, summarise, summary_table};

#[cfg(test)]
mod scene_tests;
#[cfg(test)]
mod session_tests;
#[cfg(test)]
mod tests;
