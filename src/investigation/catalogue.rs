//! The five guided investigations, as data: what each asks, how the student
//! predicts, how the scene is set up (a settings patch, applied like a preset
//! through the normal settings path), what the run measures, the prompts to
//! explain and what scientists found. The state machine (`mod.rs`) and the
//! measurements (`measure.rs`) read these; nothing here runs anything.

use crate::i18n::ts;

/// A text of the catalogue, by its message id (`inv-leader.question`): the
/// words are the string catalogue's (`locales/*/investigations.ftl`), in the
/// language in force.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Text(pub &'static str);

impl Text {
    /// The words, in the language in force.
    pub fn text(self) -> &'static str {
        ts(self.0)
    }

    /// The message id.
    pub fn id(self) -> &'static str {
        self.0
    }
}

/// How a student commits a prediction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PredictionKind {
    /// One of a few answers.
    Choice(&'static [Text]),
    /// The shape of a curve: one of the sketched [`Shape`]s, over the plot's axes.
    Curve {
        x_label: Text,
        y_label: Text,
        shapes: &'static [Shape],
    },
}

/// A sketched curve shape a student can choose: its name and its height
/// (0 to 1 of the plot's height) at five evenly spaced points across the x axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shape {
    pub name: Text,
    pub points: [f64; 5],
}

impl Shape {
    /// The sketch's height at `u` (0 to 1 across the x axis), joining its points
    /// by straight lines.
    pub fn at(&self, u: f64) -> f64 {
        let u = u.clamp(0.0, 1.0) * 4.0;
        let k = (u.floor() as usize).min(3);
        let f = u - k as f64;
        self.points[k] * (1.0 - f) + self.points[k + 1] * f
    }
}

/// The curve shapes both curve investigations offer.
pub const SHAPES: [Shape; 5] = [
    Shape {
        name: Text("inv-shape-flat"),
        points: [0.3, 0.3, 0.3, 0.3, 0.3],
    },
    Shape {
        name: Text("inv-shape-line"),
        points: [0.1, 0.3, 0.5, 0.7, 0.9],
    },
    Shape {
        name: Text("inv-shape-levels"),
        points: [0.1, 0.7, 0.85, 0.9, 0.9],
    },
    Shape {
        name: Text("inv-shape-peak"),
        points: [0.1, 0.5, 0.9, 0.5, 0.1],
    },
    Shape {
        name: Text("inv-shape-down"),
        points: [0.9, 0.7, 0.5, 0.3, 0.1],
    },
];

/// What an explain prompt refers to, so the window shows it beside the
/// question (the result shrinks to its summary line otherwise).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shows {
    /// The question needs no picture (or looks at the tank, which the
    /// investigation window never covers: see `ui::investigation_panel::dock`).
    Words,
    /// The result's chart: the bars, or the measured curve with the sketch.
    Result,
    /// The counts over the run (the catches plot).
    Timelines,
}

/// One explain prompt: its words and what it asks the student to look at.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Prompt {
    pub words: Text,
    pub shows: Shows,
}

impl Prompt {
    /// The question, in the language in force.
    pub fn text(self) -> &'static str {
        self.words.text()
    }
}

const fn prompt(id: &'static str, shows: Shows) -> Prompt {
    Prompt {
        words: Text(id),
        shows,
    }
}

/// What a run measures (see `measure.rs`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MeasurementKind {
    /// The lab's own two tanks from their start for `secs` simulated seconds:
    /// the sharks' catches in each.
    CatchesInBothTanks { secs: f64 },
    /// The live tank's polarization with alignment at its setting and at 0,
    /// each over `secs` simulated seconds once the school had `settle_secs`
    /// to change; and which fish the student clicked.
    AlignmentOnOff { settle_secs: f64, secs: f64 },
    /// An experiment (the experiment engine's design, JSON): its summary is the
    /// measured curve.
    Sweep { design: &'static str },
    /// The muscle body's speed at full amplitude at each tail-beat frequency
    /// (Hz), `secs` simulated seconds each, speed over the second half.
    TailBeat {
        frequencies_hz: &'static [f64],
        secs: f64,
    },
    /// The learning lab: train the first drill, then race the copies saved
    /// along the way for `secs` simulated seconds.
    LearningRace { secs: f64 },
}

/// One guided investigation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Investigation {
    /// The link's and the API's name (`?investigation=why-school`).
    pub id: &'static str,
    pub title: Text,
    /// One line for the list.
    pub teaser: Text,
    /// Class time, minutes.
    pub minutes: u32,
    /// The first screen: what we are going to look at.
    pub intro: Text,
    /// The question the prediction answers.
    pub question: Text,
    pub prediction: PredictionKind,
    /// The settings patch that sets up the scene (`shoal.set()`'s format).
    pub setup: &'static str,
    /// What to watch during the run.
    pub run_hint: Text,
    pub measurement: MeasurementKind,
    /// Two or three prompts to explain, one at a time.
    pub prompts: &'static [Prompt],
    /// What scientists found, and how our model compares.
    pub reveal: Text,
    /// The references, in one line.
    pub reference: Text,
}

impl Investigation {
    /// Every text of the investigation, by its message id: what it names of
    /// the catalogue (a test makes sure each exists in every language).
    pub fn texts(&self) -> Vec<Text> {
        let mut out = vec![
            self.title,
            self.teaser,
            self.intro,
            self.question,
            self.run_hint,
            self.reveal,
            self.reference,
        ];
        match self.prediction {
            PredictionKind::Choice(choices) => out.extend_from_slice(choices),
            PredictionKind::Curve {
                x_label,
                y_label,
                shapes,
            } => {
                out.extend([x_label, y_label]);
                out.extend(shapes.iter().map(|s| s.name));
            }
        }
        out.extend(self.prompts.iter().map(|p| p.words));
        out
    }
}

/// Every investigation, in the order of the list.
pub const INVESTIGATIONS: [Investigation; 5] = [
    Investigation {
        id: "why-school",
        title: Text("inv-why-school"),
        teaser: Text("inv-why-school.teaser"),
        minutes: 10,
        intro: Text("inv-why-school.intro"),
        question: Text("inv-why-school.question"),
        prediction: PredictionKind::Choice(&[
            Text("inv-why-school.choice-loners"),
            Text("inv-why-school.choice-school"),
            Text("inv-why-school.choice-same"),
        ]),
        setup: r#"{"scene": "boids", "compare": true, "paused": false, "seed": 6,
                   "show_vision": false,
                   "left": {"preset": "individual", "fish_count": 40, "sharks": 1,
                            "stingrays": 0, "selected": null},
                   "right": {"preset": "group", "fish_count": 40, "sharks": 1,
                             "stingrays": 0, "selected": null}}"#,
        run_hint: Text("inv-why-school.run-hint"),
        measurement: MeasurementKind::CatchesInBothTanks { secs: 180.0 },
        prompts: &[
            prompt("inv-why-school.prompt-1", Shows::Timelines),
            prompt("inv-why-school.prompt-2", Shows::Words),
            prompt("inv-why-school.prompt-3", Shows::Words),
        ],
        reveal: Text("inv-why-school.reveal"),
        reference: Text("inv-why-school.reference"),
    },
    Investigation {
        id: "leader",
        title: Text("inv-leader"),
        teaser: Text("inv-leader.teaser"),
        minutes: 10,
        intro: Text("inv-leader.intro"),
        question: Text("inv-leader.question"),
        prediction: PredictionKind::Choice(&[
            Text("inv-leader.choice-yes"),
            Text("inv-leader.choice-no"),
        ]),
        setup: r#"{"scene": "boids", "compare": false, "paused": false, "seed": 3,
                   "show_vision": false,
                   "left": {"preset": "group", "fish_count": 60, "sharks": 0,
                            "stingrays": 0, "selected": null}}"#,
        run_hint: Text("inv-leader.run-hint"),
        measurement: MeasurementKind::AlignmentOnOff {
            settle_secs: 5.0,
            secs: 10.0,
        },
        prompts: &[
            prompt("inv-leader.prompt-1", Shows::Words),
            prompt("inv-leader.prompt-2", Shows::Result),
            prompt("inv-leader.prompt-3", Shows::Words),
        ],
        reveal: Text("inv-leader.reveal"),
        reference: Text("inv-leader.reference"),
    },
    Investigation {
        id: "which-urge",
        title: Text("inv-which-urge"),
        teaser: Text("inv-which-urge.teaser"),
        minutes: 12,
        intro: Text("inv-which-urge.intro"),
        question: Text("inv-which-urge.question"),
        prediction: PredictionKind::Curve {
            x_label: Text("inv-which-urge.x-label"),
            y_label: Text("inv-which-urge.y-label"),
            shapes: &SHAPES,
        },
        setup: r#"{"scene": "boids", "compare": false, "paused": false, "seed": 1,
                   "left": {"preset": "group", "fish_count": 60, "sharks": 0,
                            "stingrays": 0, "selected": null}}"#,
        run_hint: Text("inv-which-urge.run-hint"),
        measurement: MeasurementKind::Sweep {
            design: concat!(
                r#"{"name": "which-urge", "#,
                r#""description": "polarization against alignment", "#, // words: the design's name, not shown
                r#""settings": {"scene": "boids","#,
                r#"
                                     "left": {"preset": "group", "fish_count": 60,
                                              "sharks": 0, "stingrays": 0}},
                        "factors": [{"key": "left.alignment",
                                     "levels": {"from": 0, "to": 100, "steps": 6}}],
                        "replicates": {"count": 3, "first_seed": 1},
                        "warmup_secs": 10, "measure_secs": 10,
                        "measures": [{"measure": "polarization", "summary": "mean"}]}"#
            ),
        },
        prompts: &[
            prompt("inv-which-urge.prompt-1", Shows::Result),
            prompt("inv-which-urge.prompt-2", Shows::Result),
            prompt("inv-which-urge.prompt-3", Shows::Words),
        ],
        reveal: Text("inv-which-urge.reveal"),
        reference: Text("inv-which-urge.reference"),
    },
    Investigation {
        id: "how-swim",
        title: Text("inv-how-swim"),
        teaser: Text("inv-how-swim.teaser"),
        minutes: 10,
        intro: Text("inv-how-swim.intro"),
        question: Text("inv-how-swim.question"),
        prediction: PredictionKind::Curve {
            x_label: Text("inv-how-swim.x-label"),
            y_label: Text("inv-how-swim.y-label"),
            shapes: &SHAPES,
        },
        setup: r#"{"scene": "physics", "paused": false, "seed": 1,
                   "physics": {"fish_count": 10, "sharks": 0, "behaviour": "school",
                               "current_m_per_s": 0, "selected": 0, "show_body": true,
                               "hand_control": false, "follow": false}}"#,
        run_hint: Text("inv-how-swim.run-hint"),
        measurement: MeasurementKind::TailBeat {
            frequencies_hz: &[1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0],
            secs: 30.0,
        },
        prompts: &[
            prompt("inv-how-swim.prompt-1", Shows::Result),
            prompt("inv-how-swim.prompt-2", Shows::Result),
            prompt("inv-how-swim.prompt-3", Shows::Words),
        ],
        reveal: Text("inv-how-swim.reveal"),
        reference: Text("inv-how-swim.reference"),
    },
    Investigation {
        id: "learning",
        title: Text("inv-learning"),
        teaser: Text("inv-learning.teaser"),
        minutes: 12,
        intro: Text("inv-learning.intro"),
        question: Text("inv-learning.question"),
        prediction: PredictionKind::Choice(&[
            Text("inv-learning.choice-clearly"),
            Text("inv-learning.choice-just"),
            Text("inv-learning.choice-no"),
        ]),
        setup: r#"{"scene": "learning", "paused": false, "seed": 1,
                   "learning": {"species": "shark", "annealing_steps": 6840,
                                "training": false, "controller": "learned"}}"#,
        run_hint: Text("inv-learning.run-hint"),
        measurement: MeasurementKind::LearningRace { secs: 7.4 },
        prompts: &[
            prompt("inv-learning.prompt-1", Shows::Result),
            prompt("inv-learning.prompt-2", Shows::Result),
        ],
        reveal: Text("inv-learning.reveal"),
        reference: Text("inv-learning.reference"),
    },
];

/// The investigation called `id`.
pub fn find(id: &str) -> Option<&'static Investigation> {
    INVESTIGATIONS.iter().find(|i| i.id == id)
}

/// The known ids, for a message: `why-school, leader, …`.
pub fn known_ids() -> String {
    INVESTIGATIONS
        .iter()
        .map(|i| i.id)
        .collect::<Vec<_>>()
        .join(", ")
}
