//! The five guided investigations, as data: what each asks, how the student
//! predicts, how the scene is set up (a settings patch, applied like a preset
//! through the normal settings path), what the run measures, the prompts to
//! explain and what scientists found. The state machine (`mod.rs`) and the
//! measurements (`measure.rs`) read these; nothing here runs anything.

/// How a student commits a prediction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PredictionKind {
    /// One of a few answers.
    Choice(&'static [&'static str]),
    /// The shape of a curve: one of the sketched [`Shape`]s, over the plot's axes.
    Curve {
        x_label: &'static str,
        y_label: &'static str,
        shapes: &'static [Shape],
    },
}

/// A sketched curve shape a student can choose: its name and its height
/// (0 to 1 of the plot's height) at five evenly spaced points across the x axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shape {
    pub name: &'static str,
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
        name: "Flat: it makes no difference",
        points: [0.3, 0.3, 0.3, 0.3, 0.3],
    },
    Shape {
        name: "A straight line up",
        points: [0.1, 0.3, 0.5, 0.7, 0.9],
    },
    Shape {
        name: "Up fast, then levels off",
        points: [0.1, 0.7, 0.85, 0.9, 0.9],
    },
    Shape {
        name: "Up, then down again",
        points: [0.1, 0.5, 0.9, 0.5, 0.1],
    },
    Shape {
        name: "Down",
        points: [0.9, 0.7, 0.5, 0.3, 0.1],
    },
];

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
    pub title: &'static str,
    /// One line for the list.
    pub teaser: &'static str,
    /// Class time, minutes.
    pub minutes: u32,
    /// The first screen: what we are going to look at.
    pub intro: &'static str,
    /// The question the prediction answers.
    pub question: &'static str,
    pub prediction: PredictionKind,
    /// The settings patch that sets up the scene (`shoal.set()`'s format).
    pub setup: &'static str,
    /// What to watch during the run.
    pub run_hint: &'static str,
    pub measurement: MeasurementKind,
    /// Two or three prompts to explain, one at a time.
    pub prompts: &'static [&'static str],
    /// What scientists found, and how our model compares.
    pub reveal: &'static str,
    /// The references, in one line.
    pub reference: &'static str,
}

/// Every investigation, in the order of the list.
pub const INVESTIGATIONS: [Investigation; 5] = [
    Investigation {
        id: "why-school",
        title: "Why do fish school?",
        teaser: "A shark hunts loners in one tank and a school in the other. Who loses fewer fish?",
        minutes: 10,
        intro: "Two tanks with the same 40 fish and one shark each. On the left the fish are \
                loners (the Individual urges); on the right they school (the Group urges). \
                Nothing else differs.",
        question: "In 3 minutes, which tank will lose fewer fish to its shark?",
        prediction: PredictionKind::Choice(&[
            "The loners (left)",
            "The school (right)",
            "About the same",
        ]),
        setup: r#"{"scene": "boids", "compare": true, "paused": false, "seed": 6,
                   "show_vision": false,
                   "left": {"preset": "individual", "fish_count": 40, "sharks": 1,
                            "stingrays": 0, "selected": null},
                   "right": {"preset": "group", "fish_count": 40, "sharks": 1,
                             "stingrays": 0, "selected": null}}"#,
        run_hint: "Run starts both tanks again from the same start and counts for 3 simulated \
                   minutes. Watch each shark: does it chase one fish to the end, or switch? \
                   Raise the Speed slider to get there sooner. The plot in this window counts \
                   each tank's catches.",
        measurement: MeasurementKind::CatchesInBothTanks { secs: 180.0 },
        prompts: &[
            "Look at the catches plot in this window. When did each shark catch its fish: \
             steadily, or in bursts?",
            "Watch the right shark near the school. What happens to the fish it was chasing?",
            "Why might it be harder to catch a fish in a crowd?",
        ],
        reveal: "Many predators catch fewer prey in a school. Landeau and Terborgh (1986) let \
                 largemouth bass hunt silvery minnows: a lone minnow was caught at once, but \
                 against shoals of 8 or more the bass often failed, because it kept switching \
                 targets. This is the confusion effect. Our shark has it too: each second it \
                 loses its lock on its target at a rate that grows with the number of fish \
                 close to the target, and needs a second to pick another one, so a lone fish is \
                 never lost and a fish in a tight school almost at once. Schools also see a \
                 shark sooner (many eyes) and dilute the risk; our model has the confusion and \
                 fleeing, not the many eyes. One run is one chance: over seeds 1 to 10 of this \
                 setting (in the browser) the loners lost 84 fish and the schools 55; the \
                 school lost clearly fewer in 6 runs of the 10, about as many in 3, and more \
                 in 1. Press New next to Seed and run again to see.",
        reference: "Landeau & Terborgh 1986, Anim. Behav. 34:1372; Lim & Tan, SIMBA (predator \
                    species); Shoal's shark: docs/boids.md",
    },
    Investigation {
        id: "leader",
        title: "Is there a leader?",
        teaser: "A school turns as one. Does one fish lead it?",
        minutes: 10,
        intro: "One tank of 60 schooling fish (the Group urges). Watch the school turn \
                together.",
        question: "Does one fish lead the school?",
        prediction: PredictionKind::Choice(&["Yes, one fish leads", "No, nobody leads"]),
        setup: r#"{"scene": "boids", "compare": false, "paused": false, "seed": 3,
                   "show_vision": false,
                   "left": {"preset": "group", "fish_count": 60, "sharks": 0,
                            "stingrays": 0, "selected": null}}"#,
        run_hint: "Click fish (at least one) to see what each one heeds: the white rings are \
                   the neighbours it reacts to. Then turn alignment off and on with the buttons \
                   below and watch the polarization (1: all swim the same way).",
        measurement: MeasurementKind::AlignmentOnOff {
            settle_secs: 5.0,
            secs: 10.0,
        },
        prompts: &[
            "Which neighbours did the fish you clicked pay attention to? Was any of them special?",
            "What happened to the school when alignment was off?",
            "So how can a school turn together without a leader?",
        ],
        reveal: "No fish leads. Each fish reacts only to the few neighbours it sees (here its 7 \
                 nearest, as starlings do: Ballerini et al. 2008), and the whole school's turn \
                 emerges from these local reactions. Thinking a flock or school must have a \
                 leader is a common misconception (Resnick 1996). Turning alignment off lets \
                 the fish keep together but point every way: the measured polarization shows \
                 it. Real schools do follow informed individuals sometimes (Couzin et al. 2005: \
                 a few fish that know where food is can steer a school without anyone \
                 recognising them), but no fish is in charge.",
        reference: "Resnick 1996, Beyond the centralized mindset; Ballerini et al. 2008, PNAS \
                    105:1232; Couzin et al. 2005, Nature 433:513",
    },
    Investigation {
        id: "which-urge",
        title: "Which urge makes a school?",
        teaser: "Turn the alignment urge from 0 to 100: how does the school's order change?",
        minutes: 12,
        intro: "One tank of schooling fish. The alignment urge makes a fish swim the way its \
                neighbours swim. The experiment runs the tank at six alignment weights, three \
                times each with different seeds, and measures the polarization (0: every fish \
                its own way, 1: all the same way).",
        question: "How does the school's polarization change as alignment goes from 0 to 100? \
                   Choose the shape.",
        prediction: PredictionKind::Curve {
            x_label: "alignment weight",
            y_label: "polarization",
            shapes: &SHAPES,
        },
        setup: r#"{"scene": "boids", "compare": false, "paused": false, "seed": 1,
                   "left": {"preset": "group", "fish_count": 60, "sharks": 0,
                            "stingrays": 0, "selected": null}}"#,
        run_hint: "The tank keeps swimming while the experiment runs its 18 runs in the \
                   background. Try the alignment slider yourself meanwhile.",
        measurement: MeasurementKind::Sweep {
            design: r#"{"name": "which-urge", "description": "polarization against alignment",
                        "settings": {"scene": "boids",
                                     "left": {"preset": "group", "fish_count": 60,
                                              "sharks": 0, "stingrays": 0}},
                        "factors": [{"key": "left.alignment",
                                     "levels": {"from": 0, "to": 100, "steps": 6}}],
                        "replicates": {"count": 3, "first_seed": 1},
                        "warmup_secs": 10, "measure_secs": 10,
                        "measures": [{"measure": "polarization", "summary": "mean"}]}"#,
        },
        prompts: &[
            "Where does your sketch differ most from the measured curve?",
            "Why does a little alignment already make such a difference (or not)?",
            "Is alignment alone enough to make a school? What would cohesion add?",
        ],
        reveal: "In models of this kind (Vicsek et al. 1995; Couzin et al. 2002) order appears \
                 suddenly: below some strength of alignment the group is disordered, above it \
                 the fish line up, like a phase transition. Ours measures how polarization \
                 grows with the alignment weight with the other urges fixed at the Group \
                 preset's: the interval at each point is the 95 % confidence interval of the \
                 mean over three seeds. In our tank order comes quickly: from about 0.2 \
                 without alignment to about 0.7 at a weight of 20, levelling off near 0.9 \
                 from 40 on. The rise is less sharp than a textbook transition because the \
                 tank is small (60 fish) and its walls keep turning the school.",
        reference: "Vicsek et al. 1995, Phys. Rev. Lett. 75:1226; Couzin et al. 2002, J. Theor. \
                    Biol. 218:1; Lim & Tan, SIMBA (the five urges)",
    },
    Investigation {
        id: "how-swim",
        title: "How does a fish swim?",
        teaser: "Beat the tail faster: does the fish swim faster, and without limit?",
        minutes: 10,
        intro: "A physics fish: 23 masses, 91 springs, 12 of them muscles. The muscles bend \
                the body from side to side; the water pushes back on the tail and the fish \
                moves forward. The experiment drives one body at full strength at seven tail-beat \
                frequencies and measures its speed.",
        question: "How does the fish's top speed change as its tail beats faster (1 to 5 beats \
                   a second)? Choose the shape.",
        prediction: PredictionKind::Curve {
            x_label: "tail beats per second (Hz)",
            y_label: "speed (body lengths/s)",
            shapes: &SHAPES,
        },
        setup: r#"{"scene": "physics", "paused": false, "seed": 1,
                   "physics": {"fish_count": 10, "sharks": 0, "behaviour": "school",
                               "current_m_per_s": 0, "selected": 0, "show_body": true,
                               "hand_control": false, "follow": false}}"#,
        run_hint: "The measurement swims a separate body at each beat, a little every frame. \
                   Meanwhile watch the selected fish's muscles glow red as they pull.",
        measurement: MeasurementKind::TailBeat {
            frequencies_hz: &[1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0],
            secs: 30.0,
        },
        prompts: &[
            "How much farther does the fish go for each extra beat per second?",
            "What happened at the fastest beat? Look at the muscles and the tail.",
            "Why can't a fish go faster and faster just by beating faster?",
        ],
        reveal: "Real fish swim faster the faster they beat their tail, close to a straight \
                 line over their cruising range, each beat carrying them about 0.6 to 0.7 body \
                 lengths (Bainbridge 1958; Webb's reviews); the tail beat cannot rise without \
                 limit because muscles contract only so fast. Tu and Terzopoulos' fish swims \
                 the same way, through its springs and a simple water force. Ours: speed grows \
                 about linearly up to 3 beats a second, each beat gaining only about 0.25 body \
                 lengths (our water has no added mass and the tail fin is small); above 3 beats \
                 a second each extra beat gains less, and at 5 the fish swims slower than at 4: \
                 the passive tail can no longer follow the beat, a limit of our spring model, \
                 not the muscle limit of real fish.",
        reference: "Bainbridge 1958, J. Exp. Biol. 35:109; Webb 1975, Hydrodynamics and energetics \
                    of fish propulsion; Tu & Terzopoulos 1994 §3; Shoal: docs/fish-body.md",
    },
    Investigation {
        id: "learning",
        title: "Learning to swim",
        teaser: "A fish practises swimming. Does the one that practised longer swim farther?",
        minutes: 12,
        intro: "A shark that does not know how to swim tries random muscle moves and keeps \
                the ones that take it farther (simulated annealing). Copies are saved after \
                90, 1440, 2790, 4140, 5490 and 6840 tries; then all six race.",
        question: "Will the copy that practised longest (6840 tries) swim farthest?",
        prediction: PredictionKind::Choice(&[
            "Yes, clearly farthest",
            "Yes, but only just",
            "No, practice stops helping",
        ]),
        setup: r#"{"scene": "learning", "paused": false, "seed": 1,
                   "learning": {"species": "shark", "annealing_steps": 6840,
                                "training": false, "controller": "learned"}}"#,
        run_hint: "The shark practises the first drill (swim as far as you can) a little every \
                   frame: the plot under the tank shows how well it swims. Then the six copies \
                   race.",
        measurement: MeasurementKind::LearningRace { secs: 7.4 },
        prompts: &[
            "Which copies gained the most from their extra practice?",
            "Why might the last few thousand tries help so little?",
        ],
        reveal: "Tu and Terzopoulos' shark trained for 6840 steps 'wins the race decisively'. \
                 Ours learns fast at first (the 90-try copy barely moves; the 1440-try copy is \
                 already close) and then hardly improves: the annealing has nearly converged by \
                 4140 tries, so the last copies finish within about 1 % of each other, and the \
                 longest-trained one does not always win. Learning curves of people and animals \
                 have the same shape: large early gains, small late ones (the 'power law of \
                 practice', Newell & Rosenbloom 1981).",
        reference: "Tu & Terzopoulos 1994 §4 and Fig. 7; Newell & Rosenbloom 1981; Shoal: \
                    docs/learning.md",
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
