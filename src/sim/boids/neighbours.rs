//! The neighbour stage of the boid step: the snapshot of the school that every
//! fish perceives (everyone's positions and velocities at the start of the
//! step, bucketed in a grid), and whom each fish heeds: its nearest seen
//! neighbours and the centre of the distant school it sees, searched every
//! [`NEIGHBOUR_SEARCH_EVERY_STEPS`] steps and rechecked in between.
//!
//! All fish read the same snapshot (a synchronous update), so the step's result
//! does not depend on the order in which the fish are handled.

use crate::sim::common::fmath;
use glam::Vec3;

use super::forces::{self, FarField, Perception, ViewCone};
use crate::sim::common::fish::{Fish, heading_of};
use crate::sim::common::spatial_grid::{Nearest, SpatialGrid};
use crate::sim::common::steering_tuning::SteeringTuning;
use crate::sim::common::tank::Tank;

/// How often a fish searches for the neighbours it heeds, in steps. Default 4
/// (15 times a second; chosen, not from the papers): in between, it keeps
/// heeding the same fish, rechecked every step against its field of view
/// with their positions now ([`forces::recheck_heeded`]), so it never
/// heeds a fish it cannot see; each search starts from them, so it is short.
/// Which fish are the seven nearest changes slowly: a list is at most 67 ms
/// old, in which a fish at 0.5 m/s moves 3.3 cm, under a tenth of a body
/// length. The searches are spread over the steps (fish `i` searches when
/// `i + step` is a multiple of 4), so every step costs the same. Searching
/// every step took about 60 % of a step with 20,000 fish; with this and the
/// seeded search the boid layer runs 2.2 times faster (`docs/benchmarks.md`).
pub const NEIGHBOUR_SEARCH_EVERY_STEPS: u64 = 4;

/// Side of the far field's cells as a fraction of the vision distance.
/// Default 0.5 (2.5 m for 5 m vision: 40 cells in the default tank): coarse
/// enough to be cheap for every fish, fine enough that "the cells I see" is
/// close to "the fish I see".
const FAR_FIELD_CELL_SHARE: f32 = 0.5;

/// Target mean number of fish per grid cell around a fish for the neighbour
/// search, dimensionless. Default 3: the seven nearest then mostly lie in the
/// 27 cells around a fish, so a search visits one or two rings of cells.
const FISH_PER_NEIGHBOUR_CELL: f32 = 3.0;

/// Smallest neighbour-grid cell in metres. Default 0.15 m: half the shortest
/// fish; finer cells only add empty ones.
const MIN_NEIGHBOUR_CELL_M: f32 = 0.15;

/// The school as every fish perceives it in one step: positions and velocities
/// at the start of the step, and the positions bucketed in a grid for the
/// neighbour search (the sharks look for prey in the same grid). Kept between
/// steps so that a step allocates nothing.
#[derive(Clone, Debug, Default)]
pub(super) struct Snapshot {
    positions_m: Vec<Vec3>,
    velocities_m_per_s: Vec<Vec3>,
    /// The velocities in slot order (the grid's, see [`Self::fish_at_slot`]);
    /// the positions in slot order are the grid's own copy.
    slot_velocities_m_per_s: Vec<Vec3>,
    /// Each velocity's direction in slot order (`normalize_or_zero`, zero
    /// for a still fish), worked out once per fish, not once per fish that
    /// heeds it.
    slot_directions: Vec<Vec3>,
    /// Each fish's heading in slot order ([`heading_of`] its velocity).
    slot_headings: Vec<Vec3>,
    /// The slot of each fish: `slot_of[i]` is the slot holding fish `i`.
    slot_of: Vec<u32>,
    grid: SpatialGrid,
    /// The grid's cell in the last step, metres (0 before the first): the
    /// next cell is sized from how crowded this one was.
    grid_cell_m: f32,
}

impl Snapshot {
    /// Takes the snapshot of `fish` at the start of a step and buckets it
    /// (see [`Self::rebuild_grid`]).
    pub(super) fn take(&mut self, fish: &[Fish], tank: &Tank, vision_m: f32) {
        self.positions_m.clear();
        self.positions_m.extend(fish.iter().map(|f| f.position_m));
        self.velocities_m_per_s.clear();
        self.velocities_m_per_s
            .extend(fish.iter().map(|f| f.velocity_m_per_s));
        self.rebuild_grid(tank, vision_m);
        let slots = self.grid.slots();
        self.slot_velocities_m_per_s.clear();
        self.slot_velocities_m_per_s
            .extend(slots.iter().map(|&i| self.velocities_m_per_s[i as usize]));
        self.slot_directions.clear();
        self.slot_directions.extend(
            self.slot_velocities_m_per_s
                .iter()
                .map(|v| v.normalize_or_zero()),
        );
        self.slot_headings.clear();
        self.slot_headings
            .extend(self.slot_velocities_m_per_s.iter().map(|&v| heading_of(v)));
        self.slot_of.clear();
        self.slot_of.resize(slots.len(), 0);
        for (slot, &i) in slots.iter().enumerate() {
            self.slot_of[i as usize] = slot as u32;
        }
    }

    /// Buckets the snapshot positions for the neighbour search, with cells
    /// sized so that about [`FISH_PER_NEIGHBOUR_CELL`] fish share a cell around
    /// a typical fish (judged from the last step's crowding), but never larger
    /// than `vision_m`.
    fn rebuild_grid(&mut self, tank: &Tank, vision_m: f32) {
        let n = self.positions_m.len().max(1) as f32;
        let volume_m3 = tank.size_m().element_product().max(1e-3);
        let uniform_cell_m = fmath::cbrt(volume_m3 * FISH_PER_NEIGHBOUR_CELL / n);
        let crowding = self.grid.crowding();
        let cell_m = if self.grid_cell_m > 0.0 && crowding > 0.0 {
            self.grid_cell_m * fmath::cbrt(FISH_PER_NEIGHBOUR_CELL / crowding)
        } else {
            uniform_cell_m
        };
        let cell_m = cell_m
            .min(uniform_cell_m)
            .min(vision_m.max(MIN_NEIGHBOUR_CELL_M))
            .max(MIN_NEIGHBOUR_CELL_M);
        let cell_m = if cell_m.is_finite() { cell_m } else { 1.0 };
        self.grid
            .rebuild(tank.min_m, tank.max_m, cell_m, &self.positions_m);
        self.grid_cell_m = self.grid.cell_m();
    }

    /// Everyone's position at the start of the step, metres.
    pub(super) fn positions_m(&self) -> &[Vec3] {
        &self.positions_m
    }

    /// Everyone's velocity at the start of the step, m/s.
    pub(super) fn velocities_m_per_s(&self) -> &[Vec3] {
        &self.velocities_m_per_s
    }

    /// Everyone's position at the start of the step in slot order
    /// ([`Self::fish_at_slot`]): fish near in the tank lie near in memory.
    pub(super) fn slot_positions_m(&self) -> &[Vec3] {
        self.grid.slot_positions_m()
    }

    /// Everyone's velocity at the start of the step in slot order.
    pub(super) fn slot_velocities_m_per_s(&self) -> &[Vec3] {
        &self.slot_velocities_m_per_s
    }

    /// Everyone's direction of motion in slot order (the velocity's
    /// `normalize_or_zero`).
    pub(super) fn slot_directions(&self) -> &[Vec3] {
        &self.slot_directions
    }

    /// Everyone's heading in slot order ([`heading_of`] the velocity).
    pub(super) fn slot_headings(&self) -> &[Vec3] {
        &self.slot_headings
    }

    /// The fish in each slot (`fish_slots()[slot]` is a fish's index).
    pub(super) fn fish_slots(&self) -> &[u32] {
        self.grid.slots()
    }

    /// The snapshot positions bucketed for nearest-neighbour searches.
    pub(super) fn grid(&self) -> &SpatialGrid {
        &self.grid
    }

    /// How many fish the snapshot holds.
    pub(super) fn len(&self) -> usize {
        self.positions_m.len()
    }

    /// The fish in grid order, `slot` from 0 to [`Self::len`]: neighbours of
    /// consecutive fish share cells, so handling the fish in this order keeps
    /// the searches in the cache.
    pub(super) fn fish_at_slot(&self, slot: usize) -> usize {
        self.grid.slots()[slot] as usize
    }
}

/// What one fish heeds of the school: its nearest seen neighbours and the
/// centre of the distant fish it sees ([`FarField`]).
#[derive(Clone, Copy, Debug)]
pub(super) struct Heeded {
    neighbours: Nearest,
    far_centre_m: Option<Vec3>,
}

impl Heeded {
    /// The heeded neighbours with their squared distances, nearest first.
    pub(super) fn neighbours(&self) -> &Nearest {
        &self.neighbours
    }

    /// The centre of the distant fish seen, metres; `None` when none is seen.
    pub(super) fn far_centre_m(&self) -> Option<Vec3> {
        self.far_centre_m
    }
}

/// Whom each fish heeds, kept from step to step: between two searches a fish
/// rechecks the neighbours it heeded in the last one.
///
/// The lists are kept in slot order ([`Snapshot::fish_at_slot`]) with the
/// neighbours as slots, so that the step reads its snapshot front to back and
/// a fish's neighbours lie near it in memory; each step moves them to the new
/// slots first ([`Self::begin_step`]). Renumbering changes no value and no
/// order: the same neighbours are found, nearest first, as with fish indices.
#[derive(Clone, Debug, Default)]
pub(super) struct Heeding {
    /// What each fish heeded in the last boid step, by its slot in that
    /// step, the neighbours as slots of that step.
    heeded: Vec<Heeded>,
    /// A buffer for moving the lists to the new slots (kept so that a step
    /// allocates nothing).
    moved: Vec<Heeded>,
    /// The fish in each slot of the step the lists were made in.
    fish_at_slot: Vec<u32>,
    /// The slot of each fish in that step.
    slot_of: Vec<u32>,
    far_field: FarField,
    /// Do the lists hold the last step's, made by the boid layer from the
    /// fish there are now? Otherwise the next boid step searches for everyone.
    current: bool,
    /// This step's field of view (built once per step, not once per fish;
    /// set by [`Self::begin_step`]).
    cone: ViewCone,
    /// Does every fish search this step (the first boid step, or the first
    /// after a change of settings or of the number of fish)?
    everyone_searches: bool,
    /// The world's step count at the start of this step (picks who searches).
    step: u64,
}

impl Heeding {
    /// Gets ready for boid step number `step` over `snapshot`: buckets the far
    /// field, decides whether everyone searches (after a change of settings
    /// or of the number of fish every fish does; otherwise a quarter of them,
    /// see [`NEIGHBOUR_SEARCH_EVERY_STEPS`]) and moves the last step's lists
    /// to this step's slots.
    pub(super) fn begin_step(
        &mut self,
        snapshot: &Snapshot,
        tank: &Tank,
        perception: &Perception,
        step: u64,
    ) {
        let n = snapshot.len();
        self.far_field.rebuild(
            tank.min_m,
            tank.max_m,
            perception.vision_distance_m * FAR_FIELD_CELL_SHARE,
            &snapshot.positions_m,
        );
        self.cone = ViewCone::new(perception);
        self.everyone_searches =
            !self.current || self.heeded.len() != n || self.fish_at_slot.len() != n;
        self.step = step;
        if self.everyone_searches {
            self.heeded.clear();
            self.heeded.resize(
                n,
                Heeded {
                    neighbours: Nearest::new(0),
                    far_centre_m: None,
                },
            );
        } else {
            let (heeded, old_slot_of, old_fish_at_slot) =
                (&self.heeded, &self.slot_of, &self.fish_at_slot);
            self.moved.clear();
            self.moved.extend(snapshot.fish_slots().iter().map(|&i| {
                let last = &heeded[old_slot_of[i as usize] as usize];
                Heeded {
                    neighbours: last
                        .neighbours
                        .renumbered(|j| snapshot.slot_of[old_fish_at_slot[j as usize] as usize]),
                    far_centre_m: last.far_centre_m,
                }
            }));
            std::mem::swap(&mut self.heeded, &mut self.moved);
        }
        self.fish_at_slot.clear();
        self.fish_at_slot.extend_from_slice(snapshot.fish_slots());
        self.slot_of.clear();
        self.slot_of.extend_from_slice(&snapshot.slot_of);
    }

    /// Whom fish `i`, in `slot` of this step's snapshot, heeds this step: a
    /// fresh search when it is its turn (bounded by its last neighbours,
    /// rechecked), otherwise its last neighbours as it sees them now and the
    /// far school it last saw. The neighbours are slots.
    pub(super) fn heed(
        &mut self,
        i: usize,
        slot: usize,
        snapshot: &Snapshot,
        perception: &Perception,
        tuning: &SteeringTuning,
    ) -> &Heeded {
        let positions_m = snapshot.slot_positions_m();
        let searches = self.everyone_searches
            || (i as u64 + self.step).is_multiple_of(NEIGHBOUR_SEARCH_EVERY_STEPS);
        let known = if self.everyone_searches {
            Nearest::new(tuning.topological_neighbours)
        } else {
            forces::recheck_heeded_facing(
                positions_m,
                snapshot.slot_headings[slot],
                slot,
                &self.heeded[slot].neighbours,
                &self.cone,
            )
        };
        let heeded = if searches {
            Heeded {
                // The last neighbours, rechecked, bound the search.
                neighbours: forces::search_heeded_slots(
                    positions_m,
                    snapshot.slot_headings[slot],
                    slot,
                    &snapshot.grid,
                    perception,
                    tuning,
                    &self.cone,
                    known,
                ),
                far_centre_m: self.far_field.seen_centre_m(
                    positions_m[slot],
                    snapshot.slot_headings[slot],
                    &self.cone,
                ),
            }
        } else {
            Heeded {
                neighbours: known,
                far_centre_m: self.heeded[slot].far_centre_m,
            }
        };
        self.heeded[slot] = heeded;
        &self.heeded[slot]
    }

    /// Ends a step: the lists are the boid layer's of this step when
    /// `boid_step`, otherwise stale.
    pub(super) fn end_step(&mut self, boid_step: bool) {
        self.current = boid_step;
    }

    /// The lists no longer match the fish (their number or the boid settings
    /// changed): the next boid step searches for everyone.
    pub(super) fn forget(&mut self) {
        self.current = false;
    }

    /// Do the lists hold the last step's, made by the boid layer?
    pub(super) fn is_current(&self) -> bool {
        self.current
    }

    /// What fish `i` heeded in the last boid step, if it was there, with
    /// the neighbours as fish indices.
    pub(super) fn get(&self, i: usize) -> Option<Heeded> {
        let (slot, heeded) = self.get_in_slots(i)?;
        debug_assert_eq!(self.fish_at_slot[slot] as usize, i);
        Some(Heeded {
            neighbours: heeded
                .neighbours
                .renumbered(|j| self.fish_at_slot[j as usize]),
            far_centre_m: heeded.far_centre_m,
        })
    }

    /// Fish `i`'s slot in the last boid step and what it heeded then, with
    /// the neighbours as slots of that step (as the step computed its urges).
    pub(super) fn get_in_slots(&self, i: usize) -> Option<(usize, &Heeded)> {
        let slot = *self.slot_of.get(i)? as usize;
        Some((slot, self.heeded.get(slot)?))
    }
}
