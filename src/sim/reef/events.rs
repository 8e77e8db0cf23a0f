//! The reef's event log: readable lines ("shark 12 ate fish 3") a student can
//! follow, the intention changes worth logging, and the counters over the
//! run. Every stage that logs takes the [`EventLog`] as an explicit input.

use std::collections::VecDeque;

use serde::{Deserialize, Serialize};

use crate::sim::reef::animal::ReefAnimal;
use crate::sim::reef::mind::{Focus, Intention, Target};
use crate::sim::reef::pair::Phase;

/// Something a student can read.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ReefEvent {
    pub time_secs: f64,
    pub kind: ReefEventKind,
    pub text: String,
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
    pub(super) fn push(&mut self, time_secs: f64, kind: ReefEventKind, text: String) {
        self.logged += 1;
        if self.lines.len() == EVENT_LOG_LEN {
            self.lines.pop_front();
        }
        self.lines.push_back(ReefEvent {
            time_secs,
            kind,
            text,
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
        let name = animals[i].name(i);
        match (before.intention, after.intention, after.target) {
            (b, Intention::Escape, Some(Target::Animal(p)))
                if b != Intention::Escape
                    && self.last_escape_logged_secs[i]
                        .is_none_or(|t| time_secs - t >= ESCAPE_LOG_EVERY_SECS) =>
            {
                self.last_escape_logged_secs[i] = Some(time_secs);
                let text = format!("{name} fled from {}", animals[p as usize].name(p as usize));
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
