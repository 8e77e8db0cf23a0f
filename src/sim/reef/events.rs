//! The reef's event log: readable lines ("shark 12 ate fish 3") a student can
//! follow, the intention changes worth logging, and the counters over the
//! run. Every stage that logs takes the [`EventLog`] as an explicit input.
//!
//! A line's words come from the catalogue (`locales/*/reef.ftl`, ids
//! `reef-event-…`): each event keeps its [`Line`] (the message and what
//! fills it) so the screen and the narration write it in the language in
//! force ([`ReefEvent::words`]); `text` is the line in English, for what
//! programs read (`shoal.state()`, the CSV export, *Skip*'s outcome).

use std::collections::VecDeque;

use serde::{Deserialize, Serialize};

use crate::i18n::{Args, Lang, arg, num, tr_with, with_lang};
use crate::sim::reef::animal::{ReefAnimal, animal_name};
use crate::sim::reef::mind::{FishKind, Focus, Intention, Target};
use crate::sim::reef::pair::Phase;

/// Something a student can read.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ReefEvent {
    pub time_secs: f64,
    pub kind: ReefEventKind,
    /// The line in English whatever the screen's language: `shoal.state()`,
    /// the CSV export and test scripts read it.
    pub text: String,
    /// The line's message and values, to write it again.
    #[serde(skip)]
    pub line: Line,
}

impl ReefEvent {
    /// The line in the language in force now, for the screen and the
    /// narration.
    pub fn words(&self) -> String {
        if self.line.id.is_empty() {
            self.text.clone()
        } else {
            self.line.render()
        }
    }
}

/// A value that fills an event's line.
#[derive(Clone, Debug, PartialEq)]
pub enum Word {
    /// An animal, named by its kind and index ("shark 3").
    Animal(FishKind, u32),
    /// A number shown with this many decimals.
    Number(f64, usize),
    /// A whole number.
    Count(u32),
    /// A key a message chooses its words by (a courtship phase).
    Key(&'static str),
}

/// An event's line: a catalogue message and the values that fill it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Line {
    id: &'static str,
    args: Vec<(&'static str, Word)>,
}

impl Line {
    /// The message `id` of `locales/*/reef.ftl`.
    pub fn new(id: &'static str) -> Self {
        Self {
            id,
            args: Vec::new(),
        }
    }

    /// `$name` is animal `i` of `animals`.
    pub fn animal(mut self, name: &'static str, animals: &[ReefAnimal], i: usize) -> Self {
        self.args
            .push((name, Word::Animal(animals[i].habits.kind, i as u32)));
        self
    }

    /// `$name` is an animal of `kind` numbered `i`.
    pub fn animal_of(mut self, name: &'static str, kind: FishKind, i: usize) -> Self {
        self.args.push((name, Word::Animal(kind, i as u32)));
        self
    }

    /// `$name` is `value` with `decimals` decimals.
    pub fn number(mut self, name: &'static str, value: f64, decimals: usize) -> Self {
        self.args.push((name, Word::Number(value, decimals)));
        self
    }

    /// `$name` is the whole number `n`.
    pub fn count(mut self, name: &'static str, n: u32) -> Self {
        self.args.push((name, Word::Count(n)));
        self
    }

    /// `$name` is the key `key` (a message's selector).
    pub fn key(mut self, name: &'static str, key: &'static str) -> Self {
        self.args.push((name, Word::Key(key)));
        self
    }

    /// The line in the language in force.
    pub fn render(&self) -> String {
        let mut args = Args::new();
        for (name, word) in &self.args {
            let value = match *word {
                Word::Animal(kind, i) => arg(animal_name(kind, i as usize)),
                Word::Number(x, decimals) => num(x, decimals),
                Word::Count(n) => arg(n),
                Word::Key(k) => arg(k),
            };
            args.set(*name, value);
        }
        tr_with(self.id, &args)
    }
}

/// The key of a courtship phase in the catalogue's messages.
pub fn phase_key(phase: Phase) -> &'static str {
    match phase {
        Phase::Looping => "looping",
        Phase::Circling => "circling",
        Phase::Ascending => "ascending",
        Phase::Nuzzling => "nuzzling",
        Phase::Spawned => "spawned",
    }
}

/// What happened.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum ReefEventKind {
    AtePrey {
        predator: u32,
        prey: u32,
    },
    AteFood {
        fish: u32,
    },
    BeganEscape {
        fish: u32,
        predator: u32,
    },
    BeganMating {
        fish: u32,
        partner: u32,
    },
    Courtship {
        male: u32,
        female: u32,
        phase: Phase,
    },
    LeftForLarger {
        female: u32,
        old: u32,
        new: u32,
    },
    BrokeUp {
        male: u32,
        female: u32,
    },
    /// A strike that failed: the prey around the target confused the predator.
    Missed {
        predator: u32,
        prey: u32,
        /// Other prey near the target.
        crowd: u32,
    },
    Intention {
        fish: u32,
    },
    /// A female who saw more than one male chose `male` (see
    /// [`crate::sim::reef::courtship`]: she ranks bigger males first); `over` is
    /// the biggest of the others she saw.
    Chose {
        female: u32,
        male: u32,
        over: u32,
    },
    /// The prey school came apart into `groups` groups (`fish` is in the
    /// second largest); see `reef/school_watch.rs`.
    SchoolSplit {
        fish: u32,
        groups: u32,
    },
    /// The prey school is one group again (`fish` is in it).
    SchoolJoined {
        fish: u32,
    },
    /// The prey school came within reach of the *School meets obstacle*
    /// demo's pillar (`fish` is the nearest).
    SchoolAtPillar {
        fish: u32,
    },
    /// The whole prey school went by the pillar without coming apart.
    SchoolPassedWhole {
        fish: u32,
    },
}

impl ReefEventKind {
    /// The animal the event is about, whom a click on its line selects: the
    /// one who acted (the shark that ate or missed, the fish that fled, ate or
    /// began mating), the female in courtship (she chooses).
    pub fn subject(&self) -> u32 {
        match *self {
            Self::AtePrey { predator, .. } | Self::Missed { predator, .. } => predator,
            Self::AteFood { fish }
            | Self::BeganEscape { fish, .. }
            | Self::BeganMating { fish, .. }
            | Self::Intention { fish }
            | Self::SchoolSplit { fish, .. }
            | Self::SchoolJoined { fish }
            | Self::SchoolAtPillar { fish }
            | Self::SchoolPassedWhole { fish } => fish,
            Self::Courtship { female, .. }
            | Self::LeftForLarger { female, .. }
            | Self::BrokeUp { female, .. }
            | Self::Chose { female, .. } => female,
        }
    }

    /// The kind's name, as `shoal.state()` spells it (`"ate_prey"`, …).
    pub fn name(self) -> &'static str {
        match self {
            Self::AtePrey { .. } => "ate_prey",
            Self::AteFood { .. } => "ate_food",
            Self::BeganEscape { .. } => "began_escape",
            Self::BeganMating { .. } => "began_mating",
            Self::Courtship { .. } => "courtship",
            Self::LeftForLarger { .. } => "left_for_larger",
            Self::BrokeUp { .. } => "broke_up",
            Self::Missed { .. } => "missed",
            Self::Intention { .. } => "intention",
            Self::Chose { .. } => "chose",
            Self::SchoolSplit { .. } => "school_split",
            Self::SchoolJoined { .. } => "school_joined",
            Self::SchoolAtPillar { .. } => "school_at_pillar",
            Self::SchoolPassedWhole { .. } => "school_passed_whole",
        }
    }
}

/// Seconds between two "fled" events of one fish.
pub const ESCAPE_LOG_EVERY_SECS: f64 = 15.0;
/// Events kept in the log.
pub const EVENT_LOG_LEN: usize = 200;

/// Counters over the run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ReefCounts {
    pub prey_eaten: u32,
    /// Strikes that failed because other prey near the target confused the
    /// predator (see [`crate::sim::reef::params::ReefParams::confusion_per_neighbour`]).
    pub missed_strikes: u32,
    /// Pairs that completed the courtship sequence.
    pub spawnings: u32,
    /// Of those, prey whose intention was to school when caught (not the
    /// predator's S_k, which asks whether schoolmates were around it).
    pub schooling_prey_eaten: u32,
    pub food_eaten: u32,
    /// Starts of body overlaps between two fish, not counting a bonded
    /// courting pair's (circling, ascending and nuzzling are close by design).
    pub fish_collisions: u32,
    /// Body-steps inside a rock (should stay 0).
    pub inside_rock_steps: u32,
}

/// The reef's event log: the last [`EVENT_LOG_LEN`] events, how many were
/// logged since the start, and when each fish's last escape was logged (the
/// log says "fled" once per [`ESCAPE_LOG_EVERY_SECS`], not at every glance at
/// the shark).
#[derive(Clone, Debug, Default)]
pub struct EventLog {
    lines: VecDeque<ReefEvent>,
    logged: u64,
    /// By animal index: when its last escape was logged.
    last_escape_logged_secs: Vec<Option<f64>>,
}

impl EventLog {
    /// The events kept, oldest first.
    pub fn lines(&self) -> &VecDeque<ReefEvent> {
        &self.lines
    }

    /// Events logged since the start, including those the log has dropped.
    pub fn logged(&self) -> u64 {
        self.logged
    }

    /// Logs what happened at `time_secs`.
    pub(super) fn push(&mut self, time_secs: f64, kind: ReefEventKind, line: Line) {
        let text = with_lang(Lang::En, || line.render());
        self.logged += 1;
        if self.lines.len() == EVENT_LOG_LEN {
            self.lines.pop_front();
        }
        self.lines.push_back(ReefEvent {
            time_secs,
            kind,
            text,
            line,
        });
    }

    /// Logs animal `i`'s change of focus from `before` to `after` at
    /// `time_secs`, if it is news: the start of an escape, at most once per
    /// [`ESCAPE_LOG_EVERY_SECS`].
    pub(super) fn log_decision(
        &mut self,
        animals: &[ReefAnimal],
        i: usize,
        before: Focus,
        after: Focus,
        time_secs: f64,
    ) {
        if self.last_escape_logged_secs.len() <= i {
            self.last_escape_logged_secs.resize(i + 1, None);
        }
        match (before.intention, after.intention, after.target) {
            (b, Intention::Escape, Some(Target::Animal(p)))
                if b != Intention::Escape
                    && self.last_escape_logged_secs[i]
                        .is_none_or(|t| time_secs - t >= ESCAPE_LOG_EVERY_SECS) =>
            {
                self.last_escape_logged_secs[i] = Some(time_secs);
                let text = Line::new("reef-event-fled")
                    .animal("fish", animals, i)
                    .animal("predator", animals, p as usize);
                self.push(
                    time_secs,
                    ReefEventKind::BeganEscape {
                        fish: i as u32,
                        predator: p,
                    },
                    text,
                );
            }
            _ => {}
        }
    }
}
