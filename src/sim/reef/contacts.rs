//! Counting collisions between fish for the reef's counters: the starts of
//! body overlaps, not every step two bodies overlap. Nothing here moves a
//! fish.

use crate::sim::reef::animal::ReefAnimal;
use crate::sim::reef::courtship::Courtship;
use crate::sim::reef::events::ReefCounts;

/// Two bodies whose centres are closer than this share of their mean length
/// count as colliding (0.5: their bodies overlap).
pub const COLLISION_BODY_LENGTHS: f32 = 0.5;

/// The pairs of fish whose bodies overlapped last step.
#[derive(Clone, Debug, Default)]
pub struct Contacts {
    /// Pairs in contact last step (lower index first).
    touching: Vec<(u32, u32)>,
}

impl Contacts {
    /// Finds the living pairs whose bodies overlap now (a bonded courting
    /// pair's contacts are the courtship, not collisions) and counts in
    /// `counts` those that did not overlap last step.
    pub(super) fn step(
        &mut self,
        animals: &[ReefAnimal],
        courtship: &Courtship,
        counts: &mut ReefCounts,
    ) {
        let mut now = Vec::new();
        for i in 0..animals.len() {
            if !animals[i].alive {
                continue;
            }
            for j in i + 1..animals.len() {
                if !animals[j].alive {
                    continue;
                }
                // A bonded pair chases each other's tails, rises together and
                // nuzzles: their contacts are the courtship, not collisions.
                let courting = courtship.pairs().iter().any(|p| {
                    p.bonded()
                        && ((p.male, p.female) == (i as u32, j as u32)
                            || (p.male, p.female) == (j as u32, i as u32))
                });
                if courting {
                    continue;
                }
                let (a, b) = (&animals[i].body, &animals[j].body);
                let mean = 0.5 * (a.body_length_m() + b.body_length_m());
                if a.position_m().distance(b.position_m()) < COLLISION_BODY_LENGTHS * mean {
                    now.push((i as u32, j as u32));
                }
            }
        }
        for pair in &now {
            if !self.touching.contains(pair) {
                counts.fish_collisions += 1;
            }
        }
        self.touching = now;
    }
}
