//! The reef's event log: readable lines ("shark 12 ate fish 3") a student can
//! follow, and the intention changes worth logging.

use serde::{Deserialize, Serialize};

use super::world::*;
use crate::sim::reef::courtship::Phase;
use crate::sim::reef::mind::{Focus, Intention, Target};

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

impl ReefWorld {
    pub(super) fn log_decision(&mut self, i: usize, before: Focus, after: Focus) {
        let name = self.animals[i].name(i);
        match (before.intention, after.intention, after.target) {
            (b, Intention::Escape, Some(Target::Animal(p)))
                if b != Intention::Escape
                    && self.animals[i]
                        .last_escape_logged_secs
                        .is_none_or(|t| self.time_secs - t >= ESCAPE_LOG_EVERY_SECS) =>
            {
                self.animals[i].last_escape_logged_secs = Some(self.time_secs);
                let text = format!(
                    "{name} fled from {}",
                    self.animals[p as usize].name(p as usize)
                );
                self.log(
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

    pub(super) fn log(&mut self, kind: ReefEventKind, text: String) {
        self.events_logged += 1;
        if self.events.len() == EVENT_LOG_LEN {
            self.events.pop_front();
        }
        self.events.push_back(ReefEvent {
            time_secs: self.time_secs,
            kind,
            text,
        });
    }
}
