//! The runs of the investigations, each advanced a slice per frame so the page
//! keeps drawing, each ending in an [`Outcome`] built from what it measured.
//!
//! - *Why do fish school?* reads the lab's own two tanks (the student watches
//!   them, and may raise the speed) until the simulated time is up.
//! - *Is there a leader?* reads the live tank's polarization while the student
//!   turns alignment off and on, and notes the fish they clicked.
//! - *Which urge makes a school?* is an experiment of the experiment engine
//!   ([`ExperimentSession`]), time-sliced like the *Experiment…* window's.
//! - *How does a fish swim?* swims its own muscle bodies (Tu & Terzopoulos §3:
//!   the swim motor controller at full amplitude and a chosen frequency).
//! - *Learning to swim* lets the learning lab train its first drill, then races
//!   the copies it saved on the way.

use glam::Vec3;

use super::catalogue::{MeasurementKind, PredictionKind};
use super::outcome::{Chart, CurvePoint, Outcome, Row, Timeline, curve_verdict};
use super::{Investigation, Progress};
use crate::experiment::{Design, ExperimentSession};
use crate::i18n::{num, tr, ts};
use crate::lab::Lab;
use crate::sim::body::motor_controller::{SwimMc, SwimParams};
use crate::sim::body::physical_fish::BodySpecies;
use crate::sim::body::{FishBody, PectoralFins};
use crate::tr;

/// A run under way.
pub enum Measurement {
    Catches {
        secs: f64,
    },
    Alignment(Box<AlignmentRun>),
    Sweep(Box<ExperimentSession>),
    TailBeat(Box<TailBeatRun>),
    Learning {
        secs: f64,
        raced: bool,
        /// The race's time and distances, measured on a copy of it run from its
        /// start to `secs` (to the nearest step): the same numbers however
        /// many steps the frames give the race the student watches.
        measured: Option<(f32, Vec<f32>)>,
    },
}

/// *Is there a leader?*: polarization with alignment on and off, and the fish
/// the student inspected.
pub struct AlignmentRun {
    settle_secs: f64,
    secs: f64,
    weight: Option<f32>,
    changed_at_secs: f64,
    last_sample_secs: f64,
    on: Vec<f64>,
    off: Vec<f64>,
    /// (fish, neighbours it heeded when inspected).
    pub inspected: Vec<(u32, usize)>,
    on_weight: f32,
}

/// *How does a fish swim?*: one body per frequency, one after another.
pub struct TailBeatRun {
    frequencies_hz: &'static [f64],
    secs: f64,
    current: Option<(FishBody, SwimMc, u64, Vec3)>,
    speeds: Vec<f64>,
}

impl Measurement {
    /// Starts the run of `investigation` on `lab` (already set up by the
    /// investigation's settings): resets and unpauses the scene where the run is
    /// the lab's own. A design the experiment engine refuses is a bug here,
    /// reported as text.
    pub fn start(investigation: &Investigation, lab: &mut Lab) -> Result<Self, String> {
        let unpause = |lab: &mut Lab| {
            let mut s = lab.settings().clone();
            s.paused = false;
            lab.apply_settings(s);
        };
        Ok(match investigation.measurement {
            MeasurementKind::CatchesInBothTanks { secs } => {
                unpause(lab);
                lab.reset(None);
                Self::Catches { secs }
            }
            MeasurementKind::AlignmentOnOff { settle_secs, secs } => {
                unpause(lab);
                Self::Alignment(Box::new(AlignmentRun {
                    settle_secs,
                    secs,
                    weight: None,
                    changed_at_secs: 0.0,
                    last_sample_secs: -1.0,
                    on: Vec::new(),
                    off: Vec::new(),
                    inspected: Vec::new(),
                    on_weight: lab.settings().left.alignment,
                }))
            }
            MeasurementKind::Sweep { design } => {
                let plan = Design::from_json(design)
                    .and_then(|d| d.validate())
                    .map_err(|err| tr!("inv-experiment-refused", error = err.to_string()))?;
                let guess =
                    plan.estimate().secs_one_core / plan.estimate().total_steps.max(1) as f64;
                Self::Sweep(Box::new(ExperimentSession::new(plan, guess)))
            }
            MeasurementKind::TailBeat {
                frequencies_hz,
                secs,
            } => Self::TailBeat(Box::new(TailBeatRun::new(frequencies_hz, secs))),
            MeasurementKind::LearningRace { secs } => {
                let mut s = lab.settings().clone();
                s.paused = false;
                s.learning.training = true;
                lab.apply_settings(s);
                Self::Learning {
                    secs,
                    raced: false,
                    measured: None,
                }
            }
        })
    }

    /// This frame's slice: about `budget_secs` of computing where the run has
    /// its own work, reading the lab otherwise. `Some` when the run is over.
    pub fn advance(
        &mut self,
        progress: &Progress,
        lab: &mut Lab,
        budget_secs: f64,
        now_secs: f64,
    ) -> Option<Outcome> {
        let choice = progress.prediction.map_or(0, |p| p.choice);
        let mut outcome = match self {
            Self::Catches { secs } => catches_outcome(lab, *secs, progress, choice),
            Self::Alignment(run) => run.advance(lab, progress, choice),
            Self::Sweep(session) => {
                session.slice(budget_secs, now_secs);
                (!session.running()).then(|| sweep_outcome(session, progress, choice))
            }
            Self::TailBeat(run) => run.advance(budget_secs, progress, choice),
            Self::Learning {
                secs,
                raced,
                measured,
            } => learning_advance(lab, *secs, raced, measured, progress, choice),
        };
        if let Some(outcome) = &mut outcome {
            // The same result in the other languages, from the same numbers.
            let here = crate::i18n::lang();
            for other in crate::i18n::Lang::ALL {
                if other != here
                    && let Some(t) =
                        crate::i18n::with_lang(other, || self.rebuild(progress, lab, choice))
                {
                    outcome.translations.push((other, t));
                }
            }
        }
        if outcome.is_some() && matches!(self, Self::Catches { .. }) {
            let mut s = lab.settings().clone();
            s.paused = true;
            lab.apply_settings(s);
        }
        outcome
    }

    /// The result of a run that has ended, made again (in another language):
    /// from the same numbers, measuring nothing more.
    fn rebuild(&mut self, progress: &Progress, lab: &mut Lab, choice: usize) -> Option<Outcome> {
        match self {
            Self::Catches { secs } => catches_outcome(lab, *secs, progress, choice),
            Self::Alignment(run) => run.advance(lab, progress, choice),
            Self::Sweep(session) => Some(sweep_outcome(session, progress, choice)),
            Self::TailBeat(run) => Some(run.outcome(progress, choice)),
            Self::Learning {
                secs,
                raced,
                measured,
            } => learning_advance(lab, *secs, raced, measured, progress, choice),
        }
    }

    /// How far the run is, 0 to 1, and what it is doing, in words.
    pub fn status(&self, lab: &Lab) -> (f32, String) {
        let t = lab.runs()[0].time_secs();
        match self {
            Self::Catches { secs } => (
                (t / secs) as f32,
                tr!("inv-status-catches", t = num(t, 0), secs = num(*secs, 0)),
            ),
            Self::Alignment(run) => run.status(),
            Self::Sweep(session) => {
                let p = session.progress();
                (
                    p.steps_done as f32 / p.steps_total.max(1) as f32,
                    tr!(
                        "inv-status-sweep",
                        run = (p.runs_done + 1).min(p.runs_total),
                        runs = p.runs_total
                    ),
                )
            }
            Self::TailBeat(run) => {
                let total = run.frequencies_hz.len().max(1);
                let k = run.speeds.len().min(total - 1);
                (
                    run.speeds.len() as f32 / total as f32,
                    tr!(
                        "inv-status-tail-beat",
                        hz = run.frequencies_hz[k],
                        k = k + 1,
                        total = total
                    ),
                )
            }
            Self::Learning { secs, raced, .. } => {
                let Some(l) = lab.runs()[0].scene().learning() else {
                    return (0.0, tr("inv-status-open-learning"));
                };
                match (raced, l.race()) {
                    (true, Some(race)) => (
                        0.5 + 0.5 * (f64::from(race.time_secs()) / secs) as f32,
                        tr!(
                            "inv-status-race",
                            t = num(f64::from(race.time_secs()), 1),
                            secs = num(*secs, 1)
                        ),
                    ),
                    _ => (
                        0.5 * l.trainer().evaluations() as f32 / l.annealing_steps().max(1) as f32,
                        tr!(
                            "inv-status-practising",
                            tries = l.trainer().evaluations().min(l.annealing_steps()),
                            total = l.annealing_steps()
                        ),
                    ),
                }
            }
        }
    }

    /// The simulated seconds of a run on the lab's own tanks (for the live plot).
    pub fn catches_secs(&self) -> Option<f64> {
        match self {
            Self::Catches { secs } => Some(*secs),
            _ => None,
        }
    }

    /// *Is there a leader?*'s run, to show what it has seen so far.
    pub fn alignment(&self) -> Option<&AlignmentRun> {
        match self {
            Self::Alignment(run) => Some(run),
            _ => None,
        }
    }
}

fn choice_text(progress: &Progress, choice: usize) -> &'static str {
    progress.answer_text(choice)
}

/// The verdict of a choice: does the measurement support the answer chosen?
fn choice_verdict(progress: &Progress, choice: usize, supported: usize, numbers: &str) -> String {
    if choice == supported {
        tr!(
            "inv-verdict-agrees",
            prediction = choice_text(progress, choice),
            numbers = numbers
        )
    } else {
        tr!(
            "inv-verdict-instead",
            prediction = choice_text(progress, choice),
            numbers = numbers,
            supported = choice_text(progress, supported)
        )
    }
}

/// The catches of a tank at the last sample at or before `secs`.
fn catches_at(run: &crate::lab::Run, secs: f64) -> Option<u64> {
    run.history()
        .samples()
        .filter(|s| s.time_secs <= secs + 1e-6)
        .last()
        .map(|s| s.catches)
}

/// Each tank's catches over the run's first `secs` simulated seconds, from its
/// metrics samples (what the window plots while the run goes on).
pub fn catches_timelines(lab: &Lab, secs: f64) -> Vec<Timeline> {
    let names = [ts("inv-loners"), ts("inv-school")];
    lab.runs()
        .iter()
        .zip(names)
        .map(|(run, name)| Timeline {
            label: name.to_owned(),
            points: run
                .history()
                .samples()
                .filter(|s| s.time_secs <= secs + 1e-6)
                .map(|s| [s.time_secs, s.catches as f64])
                .collect(),
        })
        .collect()
}

fn catches_outcome(lab: &Lab, secs: f64, progress: &Progress, choice: usize) -> Option<Outcome> {
    let runs = lab.runs();
    if runs[0].time_secs() < secs {
        return None;
    }
    let loners = catches_at(&runs[0], secs)?;
    let school = runs.get(1).and_then(|r| catches_at(r, secs))?;
    let supported = if loners.abs_diff(school) <= 1 {
        2
    } else if loners < school {
        0
    } else {
        1
    };
    let numbers = tr!(
        "inv-catches-summary",
        secs = num(secs, 0),
        loners = loners,
        school = school
    );
    Some(Outcome {
        summary: numbers.clone(),
        verdict: choice_verdict(progress, choice, supported, &numbers),
        rows: vec![
            Row {
                label: tr("inv-row-caught-loners"),
                value: loners as f64,
                unit: ts("inv-unit-fish"),
            },
            Row {
                label: tr("inv-row-caught-school"),
                value: school as f64,
                unit: ts("inv-unit-fish"),
            },
        ],
        chart: Chart::Bars {
            unit: ts("inv-unit-fish-caught"),
            whole: true,
        },
        timelines: catches_timelines(lab, secs),
        translations: Vec::new(),
    })
}

impl AlignmentRun {
    fn needed(&self) -> usize {
        // Samples every quarter of a simulated second.
        (self.secs * 4.0).ceil() as usize
    }

    fn status(&self) -> (f32, String) {
        let n = self.needed();
        let on = self.on.len().min(n);
        let off = self.off.len().min(n);
        // Short enough for the progress bar of a narrow window; the fish
        // clicked are named on the line under it.
        (
            (on + off) as f32 / (2 * n) as f32,
            tr!(
                "inv-status-alignment",
                on = num(on as f64 / 4.0, 0),
                off = num(off as f64 / 4.0, 0),
                secs = num(self.secs, 0)
            ),
        )
    }

    /// The mean polarization measured so far with alignment on and off.
    pub fn means(&self) -> (Option<f64>, Option<f64>) {
        let n = self.needed();
        let mean = |v: &[f64]| {
            let tail = &v[v.len().saturating_sub(n)..];
            (!tail.is_empty()).then(|| tail.iter().sum::<f64>() / tail.len() as f64)
        };
        (mean(&self.on), mean(&self.off))
    }

    fn advance(&mut self, lab: &Lab, progress: &Progress, choice: usize) -> Option<Outcome> {
        let run = &lab.runs()[0];
        let now = run.time_secs();
        let weight = lab.settings().left.alignment;
        if now + 1e-9 < self.last_sample_secs {
            // The tank was reset: start watching again from its start.
            self.last_sample_secs = -1.0;
            self.changed_at_secs = now;
        }
        if self.weight != Some(weight) {
            self.weight = Some(weight);
            self.changed_at_secs = now;
            if weight > 0.0 {
                self.on_weight = weight;
            }
        }
        if let Some(fish) = lab.settings().left.selected
            && !self.inspected.iter().any(|&(f, _)| f == fish)
            && let Some(attention) = run.scene().attention(fish as usize)
        {
            self.inspected.push((fish, attention.neighbours.len()));
        }
        for sample in run.history().samples() {
            if sample.time_secs <= self.last_sample_secs {
                continue;
            }
            self.last_sample_secs = sample.time_secs;
            if sample.time_secs - self.changed_at_secs >= self.settle_secs {
                let p = f64::from(sample.polarization);
                if weight > 0.0 {
                    self.on.push(p);
                } else {
                    self.off.push(p);
                }
            }
        }
        let n = self.needed();
        if self.on.len() < n || self.off.len() < n || self.inspected.is_empty() {
            return None;
        }
        let (Some(on), Some(off)) = self.means() else {
            return None;
        };
        let fish: Vec<String> = self
            .inspected
            .iter()
            .map(|&(f, k)| tr!("inv-fish-heeded", fish = f, count = k))
            .collect();
        let most_heeded = self.inspected.iter().map(|&(_, k)| k).max().unwrap_or(0);
        // No fish leads: every fish inspected reacted to a few neighbours only,
        // and the order vanished without alignment.
        let supported = usize::from(most_heeded <= 7 && on > off);
        let numbers = tr!(
            "inv-alignment-summary",
            fish = fish.join(", "),
            weight = num(f64::from(self.on_weight), 0),
            on = num(on, 2),
            off = num(off, 2),
            secs = num(self.secs, 0)
        );
        let mut rows = vec![
            Row {
                label: tr!(
                    "inv-row-alignment-on",
                    weight = num(f64::from(self.on_weight), 0)
                ),
                value: on,
                unit: "0-1",
            },
            Row {
                label: tr("inv-row-alignment-off"),
                value: off,
                unit: "0-1",
            },
        ];
        rows.extend(self.inspected.iter().map(|&(f, k)| Row {
            label: tr!("inv-row-heeded", fish = f),
            value: k as f64,
            unit: ts("inv-unit-fish"),
        }));
        Some(Outcome {
            summary: numbers.clone(),
            verdict: choice_verdict(progress, choice, supported, &numbers),
            rows,
            chart: Chart::Bars {
                unit: ts("inv-unit-polarization"),
                whole: false,
            },
            timelines: Vec::new(),
            translations: Vec::new(),
        })
    }
}

fn sweep_outcome(session: &ExperimentSession, progress: &Progress, choice: usize) -> Outcome {
    let rows = session.experiment().summary();
    let points: Vec<CurvePoint> = rows
        .iter()
        .filter_map(|r| {
            let x = r.levels.first()?.as_f64()?;
            let finite = |v: f64| if v.is_finite() { v } else { r.mean };
            Some(CurvePoint {
                x,
                mean: r.mean,
                low: finite(r.ci95_low),
                high: finite(r.ci95_high),
            })
        })
        .collect();
    curve_outcome(progress, choice, points, 1.0, ts("inv-what-polarization"))
}

/// A measured curve against a sketched prediction.
fn curve_outcome(
    progress: &Progress,
    choice: usize,
    points: Vec<CurvePoint>,
    y_max: f64,
    what: &str,
) -> Outcome {
    let PredictionKind::Curve {
        x_label,
        y_label,
        shapes,
    } = progress.investigation.prediction
    else {
        unreachable!("curve outcomes belong to curve predictions")
    };
    let (x_label, y_label) = (x_label.text(), y_label.text());
    let describe = |p: &CurvePoint| tr!("inv-curve-point", value = num(p.mean, 2), x = p.x);
    let summary = match (points.first(), points.last()) {
        (Some(first), Some(last)) => {
            let peak = points
                .iter()
                .max_by(|a, b| a.mean.total_cmp(&b.mean))
                .unwrap_or(last);
            tr!(
                "inv-curve-summary",
                what = what,
                first = describe(first),
                x_label = x_label,
                last = describe(last),
                peak = describe(peak)
            )
        }
        _ => tr!("inv-curve-none", what = what),
    };
    let rows = points
        .iter()
        .map(|p| Row {
            label: tr!(
                "inv-row-curve",
                y_label = y_label,
                x_label = x_label,
                x = p.x
            ),
            value: p.mean,
            unit: "",
        })
        .collect();
    Outcome {
        verdict: curve_verdict(shapes, choice, &points, y_max),
        summary,
        rows,
        chart: Chart::Curve {
            x_label,
            y_label,
            points,
            y_max,
        },
        timelines: Vec::new(),
        translations: Vec::new(),
    }
}

/// Length of the measured body, metres: the physics scene's fish.
fn body_length_m() -> f32 {
    BodySpecies::Fish.body_length_m()
}

/// Parameters of the swim motor controller at full amplitude and `hz`.
fn swim_at(hz: f64) -> SwimParams {
    SwimParams {
        anterior_amplitude: 1.0,
        anterior_frequency_hz: hz as f32,
        posterior_amplitude: 1.0,
        posterior_frequency_hz: hz as f32,
    }
}

impl TailBeatRun {
    /// One body step of the body swimming now; true when all are done.
    fn step_once(&mut self) -> bool {
        let Some(&hz) = self.frequencies_hz.get(self.speeds.len()) else {
            return true;
        };
        let length = body_length_m();
        let (body, mc, steps, half) = self.current.get_or_insert_with(|| {
            (
                FishBody::new(length, Vec3::ZERO, Vec3::X),
                SwimMc::default(),
                0,
                Vec3::ZERO,
            )
        });
        let params = swim_at(hz);
        let dt = body.dt_secs();
        let total = (self.secs / f64::from(dt)).round() as u64;
        body.step_with(&PectoralFins::NEUTRAL, Vec3::ZERO, |t| {
            mc.muscles_at(&params, t)
        });
        mc.advance(&params, dt);
        *steps += 1;
        if *steps == total / 2 {
            *half = body.centre_of_mass_m();
        }
        if *steps >= total {
            let secs = f64::from(dt) * (total - total / 2) as f64;
            let speed = f64::from((body.centre_of_mass_m() - *half).x) / secs / f64::from(length);
            self.speeds.push(speed);
            self.current = None;
        }
        self.speeds.len() >= self.frequencies_hz.len()
    }

    /// Runs all bodies to the end (tests).
    pub fn run_to_end(&mut self) {
        while !self.step_once() {}
    }

    fn advance(&mut self, budget_secs: f64, progress: &Progress, choice: usize) -> Option<Outcome> {
        let started = web_time::Instant::now();
        let mut done = self.speeds.len() >= self.frequencies_hz.len();
        while !done {
            for _ in 0..4 {
                done = self.step_once();
                if done {
                    break;
                }
            }
            if started.elapsed().as_secs_f64() >= budget_secs {
                break;
            }
        }
        done.then(|| self.outcome(progress, choice))
    }

    fn outcome(&self, progress: &Progress, choice: usize) -> Outcome {
        let points: Vec<CurvePoint> = self
            .frequencies_hz
            .iter()
            .zip(&self.speeds)
            .map(|(&x, &v)| CurvePoint {
                x,
                mean: v,
                low: v,
                high: v,
            })
            .collect();
        let top = points.iter().map(|p| p.mean).fold(0.0, f64::max);
        // The sketches' top (0.9 of the height) at the fastest measured speed.
        curve_outcome(
            progress,
            choice,
            points,
            (top / 0.9).max(1e-6),
            ts("inv-what-speed"),
        )
    }

    /// The speeds measured so far, body lengths per second.
    pub fn speeds(&self) -> &[f64] {
        &self.speeds
    }
}

impl TailBeatRun {
    /// A run at `frequencies_hz`, `secs` each (tests).
    pub fn new(frequencies_hz: &'static [f64], secs: f64) -> Self {
        Self {
            frequencies_hz,
            secs,
            current: None,
            speeds: Vec::new(),
        }
    }
}

fn learning_advance(
    lab: &mut Lab,
    secs: f64,
    raced: &mut bool,
    measured: &mut Option<(f32, Vec<f32>)>,
    progress: &Progress,
    choice: usize,
) -> Option<Outcome> {
    if !*raced {
        let l = lab.learning_mut()?;
        if l.race_entrants().is_empty() {
            return None;
        }
        l.start_race().ok()?;
        *raced = true;
        let mut copy = lab.runs()[0].scene().learning()?.race()?.clone();
        copy.run(secs as f32);
        *measured = Some((copy.time_secs(), copy.distances_m()));
        return None;
    }
    // The student watches the race reach the measured time.
    let race = lab.runs()[0].scene().learning()?.race()?;
    if f64::from(race.time_secs()) + 1e-6 < secs {
        return None;
    }
    let (time_secs, distances) = measured.as_ref()?;
    let distances: Vec<f64> = distances.iter().copied().map(f64::from).collect();
    let steps: Vec<u64> = race.entrants().map(|e| e.annealing_steps).collect();
    let (&last, others) = distances.split_last()?;
    let best_other = others.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let margin = (last - best_other) / best_other.abs().max(1e-9);
    let supported = if margin > 0.05 {
        0
    } else if margin >= 0.0 {
        1
    } else {
        2
    };
    let percent = crate::i18n::fmt(100.0 * margin, 1);
    let margin_text = if percent.starts_with('−') {
        percent
    } else {
        format!("+{percent}")
    };
    let numbers = tr!(
        "inv-race-summary",
        secs = num(f64::from(*time_secs), 1),
        tries = steps.last().copied().unwrap_or(0),
        last = num(last, 2),
        best = num(best_other, 2),
        margin = margin_text,
        first_tries = steps.first().copied().unwrap_or(0),
        first = num(distances.first().copied().unwrap_or(0.0), 2)
    );
    Some(Outcome {
        summary: numbers.clone(),
        verdict: choice_verdict(progress, choice, supported, &numbers),
        rows: steps
            .iter()
            .zip(&distances)
            .map(|(s, d)| Row {
                label: tr!("inv-row-distance", tries = *s),
                value: *d,
                unit: "m",
            })
            .collect(),
        chart: Chart::Bars {
            unit: ts("inv-unit-metres-swum"),
            whole: false,
        },
        timelines: Vec::new(),
        translations: Vec::new(),
    })
}
