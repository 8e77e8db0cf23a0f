//! Watching the prey school for the event log: when it comes apart into
//! groups, when it is one group again, and in the *School meets obstacle*
//! demo when it reaches the pillar and whether it went by whole. These
//! events only report what the fish did; nothing here changes how they swim.
//!
//! A group is the school metrics' group (fish linked by gaps of at most
//! [`crate::sim::common::school_metrics::GROUP_LINK_BODY_LENGTHS`] body lengths) of at least
//! [`MIN_GROUP_FISH`] fish; a count must hold for [`HOLD_SECS`] before the log
//! reports it, so a fish that strays for a moment or a school that touches
//! again for an instant is not news.

use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::Obstacle;
use crate::sim::common::school_metrics::group_labels;
use crate::sim::common::tank::Tank;
use crate::sim::reef::animal::ReefAnimal;
use crate::sim::reef::demos::ReefScene;
use crate::sim::reef::events::{EventLog, Line, ReefEventKind};
use crate::sim::reef::mind::FishKind;

/// Seconds between two looks at the school (0.5, chosen: a school of fish a
/// few tens of centimetres long changes shape over seconds).
pub const CHECK_EVERY_SECS: f64 = 0.5;
/// Seconds a new number of groups must last before the log reports it (1.5,
/// chosen: three looks in a row; shorter, a fish weaving at the edge of the
/// link distance made the school "split" and "join" every second).
pub const HOLD_SECS: f64 = 1.5;
/// Fewest fish that make a group worth naming (3, chosen: one or two
/// stragglers are not a second school).
pub const MIN_GROUP_FISH: usize = 3;
/// Fewest living prey that are watched as a school (4).
pub const MIN_SCHOOL_FISH: usize = 4;
/// How near the pillar's surface the nearest fish must come for the school to
/// have reached it, metres (1.0, about two body lengths of the demo's prey:
/// the front of the school starts to turn aside there).
pub const PILLAR_REACH_M: f32 = 1.0;
/// How far beyond the pillar's far side the school's mean position must be
/// for it to have gone by, metres (1.0).
pub const PAST_PILLAR_M: f32 = 1.0;

/// What the log has said about the school so far.
#[derive(Clone, Debug, Default)]
pub struct SchoolWatch {
    next_check_secs: f64,
    /// Groups the log last took as the school's state (0: not yet one school).
    groups: u32,
    /// A split was logged and no join since.
    split: bool,
    /// The count seen at the last look and since when.
    candidate: u32,
    candidate_since_secs: f64,
    /// The school has reached the pillar / gone by it.
    at_pillar: bool,
    passed: bool,
    /// It came apart after reaching the pillar.
    split_at_pillar: bool,
}

/// What the school watch reads besides the animals: the clock, the demo
/// (the pillar is watched in *School meets obstacle* only), the rocks and
/// the tank.
pub(super) struct WatchInputs<'a> {
    pub time_secs: f64,
    pub scene: ReefScene,
    pub obstacles: &'a [Obstacle],
    pub tank: &'a Tank,
}

impl SchoolWatch {
    /// Looks at the prey school every [`CHECK_EVERY_SECS`] and logs what
    /// changed.
    pub(super) fn step(
        &mut self,
        animals: &[ReefAnimal],
        log: &mut EventLog,
        inputs: &WatchInputs,
    ) {
        if inputs.time_secs < self.next_check_secs {
            return;
        }
        self.next_check_secs += CHECK_EVERY_SECS;
        let prey: Vec<(usize, Fish)> = animals
            .iter()
            .enumerate()
            .filter(|(_, a)| a.alive)
            .filter(|(_, a)| a.habits.kind == FishKind::Prey)
            .map(|(i, a)| {
                let f = Fish::new(
                    a.body.position_m(),
                    a.body.velocity_m_per_s(),
                    a.body.body_length_m(),
                    a.hue,
                );
                (i, f)
            })
            .collect();
        if prey.len() < MIN_SCHOOL_FISH {
            return;
        }
        let fish: Vec<Fish> = prey.iter().map(|(_, f)| *f).collect();
        let groups = named_groups(&group_labels(&fish));
        self.watch_groups(&groups, &prey, log, inputs.time_secs);
        if inputs.scene == ReefScene::SchoolMeetsObstacle {
            self.watch_pillar(&prey, log, inputs);
        }
    }

    fn watch_groups(
        &mut self,
        groups: &[Vec<usize>],
        prey: &[(usize, Fish)],
        log: &mut EventLog,
        now: f64,
    ) {
        let count = groups.len() as u32;
        if count != self.candidate {
            self.candidate = count;
            self.candidate_since_secs = now;
        }
        if count == 0 || count == self.groups || now - self.candidate_since_secs < HOLD_SECS {
            return;
        }
        let before = std::mem::replace(&mut self.groups, count);
        let at_pillar = self.at_pillar && !self.passed;
        match (before, count) {
            (1, n) if n >= 2 => {
                self.split = true;
                if at_pillar {
                    self.split_at_pillar = true;
                }
                let fish = prey[groups[1][0]].0 as u32;
                let text = Line::new(if at_pillar {
                    "reef-event-school-split-at-pillar"
                } else {
                    "reef-event-school-split"
                })
                .count("groups", n);
                log.push(now, ReefEventKind::SchoolSplit { fish, groups: n }, text);
            }
            // The first state the watch sees is not news: a school that
            // starts in two groups and gathers did not "join up again".
            (b, 1) if b >= 2 && self.split => {
                self.split = false;
                let fish = prey[groups[0][0]].0 as u32;
                log.push(
                    now,
                    ReefEventKind::SchoolJoined { fish },
                    Line::new("reef-event-school-joined"),
                );
            }
            _ => {}
        }
    }

    fn watch_pillar(&mut self, prey: &[(usize, Fish)], log: &mut EventLog, inputs: &WatchInputs) {
        let Some((axis_m, radius_m)) = inputs.obstacles.iter().find_map(|o| match o {
            Obstacle::Cylinder {
                base_center_m,
                radius_m,
                ..
            } => Some((*base_center_m, *radius_m)),
            _ => None,
        }) else {
            return;
        };
        let pillar = Obstacle::Cylinder {
            base_center_m: axis_m,
            radius_m,
            height_m: inputs.tank.size_m().y,
        };
        if !self.at_pillar {
            let nearest = prey.iter().min_by(|a, b| {
                pillar
                    .signed_distance_m(a.1.position_m)
                    .total_cmp(&pillar.signed_distance_m(b.1.position_m))
            });
            if let Some(&(i, f)) = nearest
                && pillar.signed_distance_m(f.position_m) <= PILLAR_REACH_M
            {
                self.at_pillar = true;
                log.push(
                    inputs.time_secs,
                    ReefEventKind::SchoolAtPillar { fish: i as u32 },
                    Line::new("reef-event-school-at-pillar"),
                );
            }
            return;
        }
        if self.passed {
            return;
        }
        let mean_x_m = prey.iter().map(|(_, f)| f.position_m.x).sum::<f32>() / prey.len() as f32;
        if mean_x_m > axis_m.x + radius_m + PAST_PILLAR_M {
            self.passed = true;
            if !self.split_at_pillar {
                log.push(
                    inputs.time_secs,
                    ReefEventKind::SchoolPassedWhole {
                        fish: prey[0].0 as u32,
                    },
                    Line::new("reef-event-school-passed-whole"),
                );
            }
        }
    }
}

/// The groups of at least [`MIN_GROUP_FISH`] fish, each as its members'
/// positions in `labels`, largest first (ties: lowest member first).
fn named_groups(labels: &[usize]) -> Vec<Vec<usize>> {
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for (k, &label) in labels.iter().enumerate() {
        if label == k {
            groups.push((k..labels.len()).filter(|&j| labels[j] == k).collect());
        }
    }
    groups.retain(|g| g.len() >= MIN_GROUP_FISH);
    groups.sort_by(|a, b| b.len().cmp(&a.len()).then(a[0].cmp(&b[0])));
    groups
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::reef::events::ReefEvent;
    use crate::sim::reef::world::{ReefConfig, ReefWorld};

    fn events_after(scene: ReefScene, seed: u64, secs: f32) -> Vec<ReefEvent> {
        let mut w = ReefWorld::new(ReefConfig {
            seed,
            scene,
            ..ReefConfig::default()
        });
        for _ in 0..(secs / w.dt_secs()) as u32 {
            w.step();
        }
        w.events().iter().cloned().collect()
    }

    fn school_events(events: &[ReefEvent]) -> Vec<&'static str> {
        events
            .iter()
            .map(|e| e.kind.name())
            .filter(|n| n.starts_with("school"))
            .collect()
    }

    #[test]
    fn the_log_tells_the_pillar_school_reaching_splitting_at_and_rejoining() {
        // The teacher's default: seed 1, muscle bodies. Measured: at the
        // pillar at 13.5 s, split there at 17 s, joined up at 57.5 s.
        let events = events_after(ReefScene::SchoolMeetsObstacle, 1, 65.0);
        assert_eq!(
            school_events(&events),
            ["school_at_pillar", "school_split", "school_joined"]
        );
        let split = events
            .iter()
            .find(|e| e.kind.name() == "school_split")
            .expect("split");
        assert!(split.text.ends_with("at the pillar"), "{}", split.text);
    }

    #[test]
    fn a_school_that_starts_scattered_and_gathers_did_not_join_up_again() {
        // The predator demo's prey start in two loose groups (seed 2) and
        // gather at 11.5 s: no "joined up again" without a split logged first.
        let events = events_after(ReefScene::PredatorAndSchool, 2, 20.0);
        let names = school_events(&events);
        assert!(
            names.first().is_none_or(|n| *n != "school_joined"),
            "{names:?}"
        );
        // And the pillar's events belong to the pillar demo only.
        assert!(!names.contains(&"school_at_pillar"), "{names:?}");
    }

    #[test]
    fn groups_are_named_largest_first_without_stragglers() {
        // Fish 0–3 one group, 4 a straggler, 5–7 another group, 8–9 a pair.
        let labels = [0, 0, 0, 0, 4, 5, 5, 5, 8, 8];
        assert_eq!(named_groups(&labels), vec![vec![0, 1, 2, 3], vec![5, 6, 7]]);
        assert!(named_groups(&[0, 1, 2]).is_empty());
    }
}
