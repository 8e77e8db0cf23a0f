//! Tests of the reef, one file per topic: the demos, feeding, predation,
//! courtship, minds, perception, schooling round the pillar and the bodies, on
//! both bodies. The measurement scripts whose figures the docs quote are in
//! `reef/census.rs`; the helpers both use live there too. Shared here: the
//! imports and [`shark_of`].

use crate::sim::common::fmath;
use glam::Vec3;

use crate::sim::reef::animal::Seen;
use crate::sim::reef::census::{
    StrikeCensus, feeding_rate, folded_fins, pillar_outcome, prey_eaten_seeds, prey_eaten_with,
    reef, run, spawning_secs, spawning_secs_in, strike_census,
};
use crate::sim::reef::courtship::Phase;
use crate::sim::reef::demos::ReefScene;
use crate::sim::reef::events::ReefEventKind;
use crate::sim::reef::mind::habits::KindTraits;
use crate::sim::reef::mind::{FishKind, Focus, Habits, Intention, IntentionGenerator, Sex, Target};
use crate::sim::reef::perception::in_a_school;
use crate::sim::reef::world::*;

mod bodies;
mod courtship;
mod demos;
mod feeding;
mod minds;
mod perception;
mod predation;
mod schooling;

/// The (first) predator of a reef.
pub(super) fn shark_of(w: &ReefWorld) -> usize {
    w.animals()
        .iter()
        .position(|a| a.habits.kind == FishKind::Predator)
        .expect("a predator")
}
