//! *Skip to the moment*: runs the simulation ahead as fast as the machine
//! allows until the scene's moment happens (the shark's catch, the spawning),
//! then goes back a few seconds before it, so the student watches the moment
//! itself at normal speed.
//!
//! Going back is exact: the lab keeps copies of the runs every few seconds
//! while it looks ahead and puts back the newest one taken at least the
//! moment's lead time before it. The simulation is deterministic, so from
//! there the run does again exactly what it did: the skip changes when the
//! student sees the run, never the run.

use std::collections::VecDeque;

use super::{Lab, LabError, Run};
use crate::settings::Settings;
use crate::sim::scene::{FoundMoment, Moment};

/// How far ahead a skip looks before giving up, simulated seconds (600,
/// chosen: the demos' moments come within 4 minutes on every seed we tried;
/// ten minutes of a 15-fish reef take under a minute of a Chromebook's time).
pub const SKIP_LIMIT_SECS: f64 = 600.0;

/// Wall-clock seconds of looking ahead per frame (0.05, chosen: the page
/// still draws about 15 frames a second, so the progress and *Cancel* stay
/// responsive, while the simulation runs ten to thirty times faster than
/// real time).
pub const SKIP_FRAME_BUDGET_SECS: f64 = 0.05;

/// Copies of the runs kept while looking ahead (4: taken every half lead
/// time, so the newest one at least a lead time before the moment is among the
/// last four, and at most one and a half lead times before it).
const SNAPSHOTS_KEPT: usize = 4;

/// A skip under way.
pub(super) struct Skip {
    moment: Moment,
    /// Events logged before the skip started: the moment is a later one.
    events_before: u64,
    start_secs: f64,
    /// Copies of the runs and their time, oldest first, one every half lead
    /// time.
    snapshots: VecDeque<(f64, Vec<Run>)>,
}

/// How a skip under way is going.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct SkipProgress {
    pub what: &'static str,
    /// Simulated seconds looked ahead so far.
    pub searched_secs: f64,
    pub limit_secs: f64,
}

/// How a skip ended.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
#[serde(tag = "outcome", rename_all = "snake_case")]
pub enum SkipOutcome {
    /// The moment was found; the runs now stand `lead_secs` (or less, if it
    /// came sooner) before it.
    Found {
        moment: FoundMoment,
        /// The simulated time the runs were put back to.
        resumed_at_secs: f64,
    },
    /// Nothing within [`SKIP_LIMIT_SECS`]: the runs stay where the search
    /// stopped.
    NotFound {
        what: &'static str,
        searched_secs: f64,
    },
}

impl Lab {
    /// Starts looking ahead for the scene's moment (see the module doc). The
    /// frames that follow run the simulation as fast as they can until it is
    /// found; [`Lab::take_skip_outcome`] then says what happened.
    pub fn skip_to_moment(&mut self) -> Result<Moment, LabError> {
        let scene = &self.runs[0].scene;
        let moment = scene.moment().ok_or(LabError::NoMoment)?;
        let start_secs = scene.time_secs();
        self.skip = Some(Skip {
            moment,
            events_before: scene.events_logged(),
            start_secs,
            snapshots: VecDeque::from([(start_secs, self.runs.clone())]),
        });
        self.skip_outcome = None;
        Ok(moment)
    }

    /// Stops looking ahead; the runs stay where the search got to.
    pub fn cancel_skip(&mut self) {
        self.skip = None;
        self.clock.clear();
    }

    /// The skip under way, if any.
    pub fn skipping(&self) -> Option<SkipProgress> {
        let skip = self.skip.as_ref()?;
        Some(SkipProgress {
            what: skip.moment.what,
            searched_secs: self.runs[0].scene.time_secs() - skip.start_secs,
            limit_secs: SKIP_LIMIT_SECS,
        })
    }

    /// How the last skip ended (until the next skip or a rebuild).
    pub fn skip_outcome(&self) -> Option<&SkipOutcome> {
        self.skip_outcome.as_ref()
    }

    /// Skips ended since the lab was made: a panel that shows each ending
    /// once compares it with the count it last saw.
    pub fn skips_finished(&self) -> u64 {
        self.skips_finished
    }

    /// Looks ahead for up to `budget_secs` of wall-clock time (at least one
    /// step), step by step, and ends the skip when the moment is found or the
    /// limit reached.
    pub(super) fn advance_skip(&mut self, budget_secs: f64) {
        let started = web_time::Instant::now();
        loop {
            let Some(skip) = self.skip.as_mut() else {
                return;
            };
            let now = self.runs[0].scene.time_secs();
            if now - skip.snapshots.back().map_or(f64::NEG_INFINITY, |s| s.0)
                >= 0.5 * skip.moment.lead_secs
            {
                if skip.snapshots.len() == SNAPSHOTS_KEPT {
                    skip.snapshots.pop_front();
                }
                skip.snapshots.push_back((now, self.runs.clone()));
            }
            self.run_steps(1);
            let scene = &self.runs[0].scene;
            let Some(skip) = self.skip.as_mut() else {
                return;
            };
            if let Some(found) = scene.moment_since(skip.events_before) {
                let back_to = found.time_secs - skip.moment.lead_secs;
                let k = skip
                    .snapshots
                    .iter()
                    .rposition(|s| s.0 <= back_to)
                    .unwrap_or(0);
                let (resumed_at_secs, runs) = skip.snapshots.swap_remove_back(k).expect("kept");
                self.runs = runs;
                self.finish_skip(SkipOutcome::Found {
                    moment: found,
                    resumed_at_secs,
                });
                return;
            }
            let searched_secs = scene.time_secs() - skip.start_secs;
            if searched_secs >= SKIP_LIMIT_SECS {
                let what = skip.moment.what;
                self.finish_skip(SkipOutcome::NotFound {
                    what,
                    searched_secs,
                });
                return;
            }
            if started.elapsed().as_secs_f64() >= budget_secs {
                return;
            }
        }
    }

    /// Runs a skip to its end now (tests, and `shoal.skip()` with no page to
    /// draw).
    pub fn finish_skip_now(&mut self) -> Option<SkipOutcome> {
        while self.skip.is_some() {
            self.advance_skip(f64::INFINITY);
        }
        self.skip_outcome.clone()
    }

    fn finish_skip(&mut self, outcome: SkipOutcome) {
        self.skip = None;
        self.skip_outcome = Some(outcome);
        self.skips_finished += 1;
        self.clock.clear();
    }
}

/// Does a skip under way survive the change from `before` to `after`? Only
/// changes that leave the simulation alone keep it: speed, pause, which fish
/// is selected or followed, and what is drawn over the tank. Anything else
/// would make the copies taken so far a different run.
pub(super) fn skip_survives(before: &Settings, after: &Settings) -> bool {
    let world_only = |s: &Settings| {
        let mut s = s.clone();
        s.speed = 1.0;
        s.paused = false;
        s.reef.selected = None;
        s.reef.follow = false;
        s.reef.show_vision = false;
        s.reef.name_tags = false;
        s.reef.overlay = Default::default();
        s
    };
    world_only(before) == world_only(after)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lab::census::reef_demo_lab;
    use crate::sim::reef::demos::ReefScene;
    use crate::sim::reef::events::ReefEventKind;
    use glam::Vec3;

    fn positions(lab: &Lab) -> Vec<Vec3> {
        let mut out = Vec::new();
        lab.runs()[0].scene().positions_m(&mut out);
        out
    }

    #[test]
    fn a_skip_goes_back_to_just_before_the_catch_and_the_run_is_unchanged() {
        // The predator demo on its default muscle bodies: the skip finds the
        // shark's first catch and puts the run back before it.
        let mut lab = reef_demo_lab(ReefScene::PredatorAndSchool, 1);
        let moment = lab.skip_to_moment().unwrap();
        assert!(lab.skipping().is_some());
        let Some(SkipOutcome::Found {
            moment: found,
            resumed_at_secs,
        }) = lab.finish_skip_now()
        else {
            panic!("no catch found: {:?}", lab.skip_outcome());
        };
        assert!(lab.skipping().is_none());
        assert!(found.text.contains("ate"), "{}", found.text);
        let now = lab.runs()[0].scene().time_secs();
        assert_eq!(now, resumed_at_secs);
        assert!(
            found.time_secs - now >= moment.lead_secs - 1e-6,
            "resumed {now} s, catch at {} s",
            found.time_secs
        );
        assert!(found.time_secs - now <= 1.5 * moment.lead_secs + 0.1);
        // Played on from there, the catch happens again, at the same time.
        let reef = |lab: &Lab| lab.runs()[0].scene().reef().unwrap().clone();
        let steps_to_catch = ((found.time_secs - now) / lab.step_secs()).round() as u32 + 1;
        lab.step(steps_to_catch);
        let again = reef(&lab)
            .events()
            .iter()
            .find(|e| matches!(e.kind, ReefEventKind::AtePrey { .. }))
            .cloned()
            .expect("the catch happens again");
        assert_eq!((again.time_secs, again.text), (found.time_secs, found.text));
        // And the run is the very run played without skipping.
        let mut plain = reef_demo_lab(ReefScene::PredatorAndSchool, 1);
        plain.step(lab.runs()[0].scene().steps() as u32);
        assert_eq!(positions(&plain), positions(&lab));
    }

    #[test]
    fn the_pillar_skip_lands_on_what_the_school_does_not_on_its_arrival() {
        // The demo asks "does it split around it and join up again?": on the
        // teacher's default muscle bodies, seeds 1-3, a skip lands on a split
        // and the next skip on the rejoin (or on the whole school going by),
        // never on "reached the pillar".
        for seed in 1..=3 {
            let mut lab = reef_demo_lab(ReefScene::SchoolMeetsObstacle, seed);
            let mut kinds = Vec::new();
            // After a split the next skip looks for the rejoin; a school that
            // went by whole has answered the question.
            while kinds.len() < 2 && kinds.last() != Some(&"went by") {
                lab.skip_to_moment().unwrap();
                let Some(SkipOutcome::Found { moment, .. }) = lab.finish_skip_now() else {
                    panic!("seed {seed}: {kinds:?} then {:?}", lab.skip_outcome());
                };
                // The log's English line says which event it was.
                let kind = ["split", "joined", "went by", "reached"]
                    .into_iter()
                    .find(|k| moment.text.contains(k))
                    .unwrap_or("?");
                kinds.push(kind);
                // Play through the moment, so the next skip looks past it.
                let to = moment.time_secs + 0.5;
                while lab.runs()[0].scene().time_secs() < to {
                    lab.step(1);
                }
            }
            assert!(
                kinds[0] == "split" || kinds[0] == "went by",
                "seed {seed}: {kinds:?}"
            );
            if kinds[0] == "split" {
                assert!(
                    kinds[1] == "joined" || kinds[1] == "split",
                    "seed {seed}: {kinds:?}"
                );
            }
        }
    }

    #[test]
    fn a_change_to_the_world_cancels_a_skip_and_a_new_selection_does_not() {
        let mut lab = reef_demo_lab(ReefScene::Courtship, 1);
        lab.skip_to_moment().unwrap();
        let mut s = lab.settings().clone();
        s.reef.selected = Some(0);
        s.reef.follow = true;
        s.speed = 2.0;
        lab.apply_settings(s.clone());
        assert!(lab.skipping().is_some());
        s.reef.visibility_m = 3.0;
        lab.apply_settings(s);
        assert!(lab.skipping().is_none());
        assert_eq!((lab.skip_outcome(), lab.skips_finished()), (None, 0));
    }

    #[test]
    fn scenes_without_a_moment_refuse_a_skip() {
        let mut lab = Lab::new(Settings::default());
        assert_eq!(lab.skip_to_moment(), Err(LabError::NoMoment));
    }

    #[test]
    fn a_skip_runs_while_paused_and_frames_stay_within_budget() {
        let mut lab = reef_demo_lab(ReefScene::Feeding, 2);
        let mut s = lab.settings().clone();
        s.paused = true;
        lab.apply_settings(s);
        lab.skip_to_moment().unwrap();
        let started = web_time::Instant::now();
        let steps = lab.advance_frame(1.0 / 60.0, 0.0);
        assert!(steps >= 1);
        // One step of six muscle fish is far below the budget; a frame ends
        // soon after it.
        assert!(started.elapsed().as_secs_f64() < 10.0 * SKIP_FRAME_BUDGET_SECS);
    }
}
