//! Guided investigations (issue 15): predict → observe → explain.
//!
//! - [`catalogue`]: the five investigations as data ([`Investigation`]): the
//!   question, how to predict (a choice or a curve's shape), the settings patch
//!   that sets up the scene, what the run measures, the prompts and the reveal.
//! - this module: the state machine a student walks through,
//!   [`Step::Intro`] → [`Step::Predict`] → [`Step::Run`] → [`Step::Explain`] →
//!   [`Step::Reveal`]. The run cannot start before a prediction is committed,
//!   and a committed prediction cannot change.
//! - [`measure`]: the runs, each a slice per frame on the lab (or on its own
//!   bodies and experiment), producing an [`Outcome`] from measurements only.
//! - [`record`]: the student's record, one self-contained HTML file and a CSV.
//! - [`link`]: `?investigation=<id>` and `shoal.set({investigation})`, validated.
//!
//! Pure and testable natively: the egui window is `ui/investigation_panel.rs`.

pub mod catalogue;
#[cfg(not(target_arch = "wasm32"))]
pub(crate) mod census;
pub mod link;
pub mod measure;
pub mod outcome;
pub mod record;

#[cfg(test)]
mod tests;

use serde::Serialize;

pub use self::catalogue::{
    INVESTIGATIONS, Investigation, MeasurementKind, PredictionKind, Prompt, Shape, Shows, Text,
};
pub use self::measure::Measurement;
pub use self::outcome::{Chart, Outcome};

/// Where a student is in an investigation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Step {
    /// What we will look at.
    #[default]
    Intro,
    /// The question; the student commits a prediction.
    Predict,
    /// The run, the prediction beside the measured result.
    Run,
    /// Prompts to explain, one at a time.
    Explain,
    /// What scientists found; the sandbox stays open.
    Reveal,
}

impl Step {
    pub fn name(self) -> &'static str {
        match self {
            Self::Intro => "intro",
            Self::Predict => "predict",
            Self::Run => "run",
            Self::Explain => "explain",
            Self::Reveal => "reveal",
        }
    }
}

/// A committed prediction: the index of the chosen answer or shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Prediction {
    pub choice: usize,
}

/// Why a step was refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StepError {
    /// Commit a prediction first.
    NoPrediction,
    /// The prediction is locked.
    Locked,
    /// That answer does not exist.
    NoSuchAnswer { choice: usize, count: usize },
    /// Not now: this is the step named.
    WrongStep(&'static str),
    /// The run has not finished yet.
    NoResult,
}

impl std::fmt::Display for StepError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        use crate::i18n::tr;
        use crate::tr;
        let text = match self {
            Self::NoPrediction => tr("inv-error-no-prediction"),
            Self::Locked => tr("inv-error-locked"),
            Self::NoSuchAnswer { choice, count } => {
                tr!("inv-error-no-such-answer", choice = *choice, count = *count)
            }
            Self::WrongStep(step) => {
                let name = match *step {
                    "intro" => tr("inv-step-name-intro"),
                    "predict" => tr("inv-step-name-predict"),
                    "run" => tr("inv-step-name-run"),
                    "explain" => tr("inv-step-name-explain"),
                    "reveal" => tr("inv-step-name-reveal"),
                    other => other.to_owned(),
                };
                tr!("inv-error-wrong-step", step = name)
            }
            Self::NoResult => tr("inv-error-no-result"),
        };
        f.write_str(&text)
    }
}

impl std::error::Error for StepError {}

/// One student's progress through one investigation.
#[derive(Clone, Debug, PartialEq)]
pub struct Progress {
    pub investigation: &'static Investigation,
    pub step: Step,
    /// The committed prediction (locked once set).
    pub prediction: Option<Prediction>,
    /// The answer the student is choosing, before committing.
    pub pending: Option<usize>,
    /// The measured result, once the run is over.
    pub outcome: Option<Outcome>,
    /// Has the run started?
    pub run_started: bool,
    /// The student's answers to the prompts (one per prompt, possibly empty).
    pub explanations: Vec<String>,
    /// The prompt on show in the explain step.
    pub prompt: usize,
    /// The settings the run started from (its seed among them), for the
    /// record's link that runs it again.
    pub run_settings: Option<crate::settings::Settings>,
}

impl Progress {
    pub fn new(investigation: &'static Investigation) -> Self {
        Self {
            investigation,
            step: Step::Intro,
            prediction: None,
            pending: None,
            outcome: None,
            run_started: false,
            explanations: vec![String::new(); investigation.prompts.len()],
            prompt: 0,
            run_settings: None,
        }
    }

    /// How many answers (or shapes) the prediction chooses from.
    pub fn answer_count(&self) -> usize {
        match self.investigation.prediction {
            PredictionKind::Choice(options) => options.len(),
            PredictionKind::Curve { shapes, .. } => shapes.len(),
        }
    }

    /// The message id of answer `choice` (the same in every language).
    pub fn answer_key(&self, choice: usize) -> &'static str {
        match self.investigation.prediction {
            PredictionKind::Choice(options) => options.get(choice).map_or("?", |o| o.id()),
            PredictionKind::Curve { shapes, .. } => shapes.get(choice).map_or("?", |s| s.name.id()),
        }
    }

    /// The words of answer `choice`, in the language in force.
    pub fn answer_text(&self, choice: usize) -> &'static str {
        match self.investigation.prediction {
            PredictionKind::Choice(options) => options.get(choice).map_or("?", |o| o.text()),
            PredictionKind::Curve { shapes, .. } => {
                shapes.get(choice).map_or("?", |s| s.name.text())
            }
        }
    }

    /// Intro → Predict.
    pub fn begin(&mut self) {
        if self.step == Step::Intro {
            self.step = Step::Predict;
        }
    }

    /// Chooses an answer (not yet committed). Refused once committed.
    pub fn choose(&mut self, choice: usize) -> Result<(), StepError> {
        if self.prediction.is_some() {
            return Err(StepError::Locked);
        }
        let count = self.answer_count();
        if choice >= count {
            return Err(StepError::NoSuchAnswer { choice, count });
        }
        self.pending = Some(choice);
        Ok(())
    }

    /// Commits the chosen answer: from now on it cannot change.
    pub fn commit(&mut self) -> Result<(), StepError> {
        if self.prediction.is_some() {
            return Err(StepError::Locked);
        }
        if !matches!(self.step, Step::Intro | Step::Predict) {
            return Err(StepError::WrongStep(self.step.name()));
        }
        let choice = self.pending.ok_or(StepError::NoPrediction)?;
        self.prediction = Some(Prediction { choice });
        self.step = Step::Run;
        Ok(())
    }

    /// May the run start? Only after a committed prediction, once.
    pub fn can_run(&self) -> bool {
        self.prediction.is_some() && self.step == Step::Run && !self.run_started
    }

    /// Starts the run (the caller builds the [`Measurement`]).
    pub fn start_run(&mut self) -> Result<(), StepError> {
        if self.prediction.is_none() {
            return Err(StepError::NoPrediction);
        }
        if self.step != Step::Run || self.run_started {
            return Err(StepError::WrongStep(self.step.name()));
        }
        self.run_started = true;
        Ok(())
    }

    /// The run measured `outcome`.
    pub fn finish_run(&mut self, outcome: Outcome) {
        self.outcome = Some(outcome);
    }

    /// Run → Explain, once measured; Explain → next prompt, then Reveal.
    pub fn advance(&mut self) -> Result<(), StepError> {
        match self.step {
            Step::Intro => self.begin(),
            Step::Predict => self.commit()?,
            Step::Run => {
                if self.outcome.is_none() {
                    return Err(StepError::NoResult);
                }
                self.step = Step::Explain;
                self.prompt = 0;
            }
            Step::Explain => {
                if self.prompt + 1 < self.investigation.prompts.len() {
                    self.prompt += 1;
                } else {
                    self.step = Step::Reveal;
                }
            }
            Step::Reveal => {}
        }
        Ok(())
    }

    /// What the explain step shows beside the prompt on show: the plot it
    /// refers to ([`Shows::Words`] outside the explain step, or when the run
    /// measured no such plot: then there is nothing to show).
    pub fn explain_shows(&self) -> Shows {
        if self.step != Step::Explain {
            return Shows::Words;
        }
        let Some(outcome) = &self.outcome else {
            return Shows::Words;
        };
        match self.investigation.prompts.get(self.prompt).map(|p| p.shows) {
            Some(Shows::Timelines) if outcome.timelines.is_empty() => Shows::Result,
            Some(shows) => shows,
            None => Shows::Words,
        }
    }

    /// The run's seeds: the seed it started from, or an experiment's
    /// replicate seeds (empty before the run).
    pub fn seeds(&self) -> Vec<u64> {
        if let MeasurementKind::Sweep { design } = self.investigation.measurement
            && let Ok(design) = serde_json::from_str::<serde_json::Value>(design)
            && let Some(replicates) = design.get("replicates")
        {
            let count = replicates
                .get("count")
                .and_then(|c| c.as_u64())
                .unwrap_or(1);
            let first = replicates
                .get("first_seed")
                .and_then(|c| c.as_u64())
                .unwrap_or(1);
            return (first..first + count).collect();
        }
        self.run_settings.iter().map(|s| s.seed).collect()
    }

    /// The full link that opens this investigation with the settings its run
    /// started from (`page` is the page's address): open it and press Run to
    /// run it again. `None` before the run.
    pub fn rerun_link(&self, page: &str) -> Option<String> {
        let settings = self.run_settings.as_ref()?;
        Some(format!(
            "{}#{}",
            link::with_investigation(page, self.investigation.id),
            crate::settings::share_link::encode(settings)
        ))
    }

    /// `state().investigation`.
    pub fn report(&self) -> InvestigationReport {
        InvestigationReport {
            id: self.investigation.id,
            step: self.step,
            chosen: self.pending,
            prediction: self.prediction.map(|p| PredictionReport {
                choice: p.choice,
                key: self.answer_key(p.choice),
                text: self.answer_text(p.choice),
            }),
            running: self.run_started && self.outcome.is_none(),
            result: self.outcome.clone(),
            prompt: (self.step == Step::Explain).then_some(self.prompt),
            explanations: self.explanations.clone(),
        }
    }
}

/// `shoal.state().investigation`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct InvestigationReport {
    pub id: &'static str,
    pub step: Step,
    /// The answer picked, committed or not.
    pub chosen: Option<usize>,
    /// The committed prediction (locked).
    pub prediction: Option<PredictionReport>,
    /// The run is under way.
    pub running: bool,
    pub result: Option<Outcome>,
    /// The prompt on show (0-based), in the explain step.
    pub prompt: Option<usize>,
    /// The student's answers, one per prompt.
    pub explanations: Vec<String>,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PredictionReport {
    pub choice: usize,
    /// The answer's message id: the same in every language (what a class
    /// server is sent, so a class's histogram pools students who read Shoal in
    /// different languages).
    pub key: &'static str,
    pub text: &'static str,
}

/// `shoal.investigations()`: one entry per investigation.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ListEntry {
    pub id: &'static str,
    pub title: &'static str,
    pub minutes: u32,
    pub teaser: &'static str,
}

/// The list `shoal.investigations()` returns.
pub fn list() -> Vec<ListEntry> {
    INVESTIGATIONS
        .iter()
        .map(|i| ListEntry {
            id: i.id,
            title: i.title.text(),
            minutes: i.minutes,
            teaser: i.teaser.text(),
        })
        .collect()
}

/// The settings an investigation starts from: the defaults, then its patch
/// (as `shoal.set()` would apply it).
pub fn setup_settings(
    investigation: &Investigation,
) -> Result<crate::settings::Settings, crate::settings::SettingsError> {
    let patch: serde_json::Value = serde_json::from_str(investigation.setup).map_err(|err| {
        crate::settings::SettingsError::NotAnObject(format!("{} ({err})", investigation.id))
    })?;
    let mut settings = crate::settings::Settings::default();
    settings.apply_patch(&patch)?;
    Ok(settings)
}
