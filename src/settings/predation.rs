//! The two protections a school has from its predators that are our
//! additions to the papers (`Settings::predation`), for the schooling lab's
//! sharks and the reef's predators alike: the confusion effect and joint
//! flight. Both on by default; *Paper only* turns both off
//! (`shoal.set({predation: {confusion: false, joint_flight: false}})`).

use serde::{Deserialize, Serialize};

/// The confusion effect and joint flight, switched on or off.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PredationSettings {
    /// A predator is confused by the prey around its target: in the schooling
    /// lab a shark loses its lock, in the reef a strike misses more often the
    /// more prey swim near its target. Not in Reynolds nor in Tu & Terzopoulos.
    pub confusion: bool,
    /// A frightened school flees together: in the schooling lab the alarm
    /// passes from a frightened fish to its neighbours, in the reef a schooling
    /// fish flees with the schoolmates it sees. Not in the papers.
    pub joint_flight: bool,
}

impl Default for PredationSettings {
    fn default() -> Self {
        Self {
            confusion: true,
            joint_flight: true,
        }
    }
}

impl PredationSettings {
    /// The key prefix of these settings in `shoal.set` and the studio's rules.
    pub const PREFIX: &str = "predation.";

    /// Both additions off: the papers' predators and prey only.
    pub const PAPER_ONLY: Self = Self {
        confusion: false,
        joint_flight: false,
    };

    /// Are both additions off?
    pub fn is_paper_only(self) -> bool {
        self == Self::PAPER_ONLY
    }

    /// Sets the schooling lab's world tuning to these switches.
    pub fn apply_to_boids(self, params: &mut crate::sim::boids::params::BoidWorldParams) {
        params.shark.confusion = self.confusion;
        params.joint_flight = self.joint_flight;
    }

    /// Sets the reef's tuning to these switches.
    pub fn apply_to_reef(self, params: &mut crate::sim::reef::params::ReefParams) {
        params.confusion = self.confusion;
        params.joint_flight = self.joint_flight;
    }
}
