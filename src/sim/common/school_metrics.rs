//! Numbers that tell a school from a crowd of loners, computed from the fish's
//! positions and velocities (Couzin et al. 2002's order parameters, and the
//! nearest-neighbour distance of Pitcher & Partridge 1979; see `docs/boids.md`).
//!
//! - polarization p = ‖Σ v̂ᵢ‖ / N: 1 when all swim the same way, near 0 when
//!   headings are random or the group mills.
//! - milling m = Σ_g ‖Σ_{i∈g} r̂ᵢ × v̂ᵢ‖ / N over the groups g (below), r̂ᵢ the
//!   unit vector from the centre of fish i's own group to fish i: 1 when every
//!   group is a perfect torus (fish circling their group's centre), near 0
//!   otherwise. Measured about each group's centre, not the tank's, so loners
//!   that happen to circle along the glass do not read as a mill; groups of
//!   fewer than [`MIN_MILLING_GROUP`] fish count 0 (two loners passing each
//!   other would read as a perfect mill), and each group counts only the part
//!   of its turning beyond what random headings give ([`beyond_chance`]): a
//!   cluster of k loners swimming every which way turns by about 0.75/√k by
//!   chance alone. And a group counts only when it is a school: its fish
//!   keep on average at most [`MILLING_SCHOOL_NND_BODY_LENGTHS`] (1.5) body
//!   lengths from their nearest neighbour, so loose loners that drift round
//!   the tank along the glass are not read as a mill (200 loners read 0.30
//!   before these two rules, a school 0.09–0.14).
//! - mean nearest-neighbour distance, in each fish's own body lengths (schooling
//!   fish keep about one body length).
//! - groups: clusters of fish linked by gaps of at most two body lengths.

use crate::sim::common::fmath;
use glam::{IVec3, Vec3};
use serde::Serialize;

use crate::sim::common::fish::Fish;
use crate::sim::common::spatial_grid::{Nearest, SpatialGrid};

/// The school's order parameters at one instant.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct SchoolMetrics {
    pub polarization: f32,
    pub milling: f32,
    pub nnd_body_lengths: f32,
    pub groups: u32,
    pub mean_speed_m_per_s: f32,
}

/// Two fish belong to the same group when closer than this many body lengths
/// (the larger of the two). Default 2: the definition; a schooling fish
/// keeps about one body length from its neighbours.
pub const GROUP_LINK_BODY_LENGTHS: f32 = 2.0;

/// Smallest group whose swimming round its centre counts as milling (fish).
/// Default 5 (chosen): two loners passing each other head-on (or three)
/// have r̂ × v̂ pointing the same way and would read as a perfect mill; a mill
/// is a group of several fish going round together. Smaller groups count 0.
pub const MIN_MILLING_GROUP: usize = 5;

/// A group counts as milling only when it is a school: its fish are on average
/// at most this many body lengths from their nearest neighbour. Default 1.5
/// (chosen; measured on seeds 33–36, 200 fish at 40 s): Table 1's Group schools
/// keep 0.86–1.05, while the loose clouds of the Individual weights, which
/// chain into one 2-body-length-linked group of 80–140 fish and sweep round
/// the tank along the glass, keep 1.74–1.83.
pub const MILLING_SCHOOL_NND_BODY_LENGTHS: f32 = 1.5;

/// How far a group's turning `m` = ‖Σ r̂ × v̂‖ / k (0 to 1) lies beyond what
/// `k` fish with random headings give, rescaled to 0 to 1: (m − c) / (1 − c),
/// at least 0, with c = 1/√k. Random headings give about 0.75/√k (3-D) or
/// 0.56/√k (flat), so c = 1/√k is a little above chance: a group of five
/// loners (c = 0.45) reads near 0, a 200-fish school (c = 0.07) almost as
/// measured, a perfect mill 1.
fn beyond_chance(m: f32, k: u32) -> f32 {
    let chance = 1.0 / (k as f32).sqrt();
    ((m - chance) / (1.0 - chance)).max(0.0)
}

/// Computes the metrics once. A convenience for one-off measurements;
/// [`SchoolMeter`] keeps its buffers between calls.
pub fn measure(fish: &[Fish], tank_min_m: Vec3, tank_max_m: Vec3) -> SchoolMetrics {
    SchoolMeter::default().measure(fish, tank_min_m, tank_max_m)
}

/// Target number of fish per cell, as a fish sees it, of the grid for the
/// nearest-neighbour distance (dimensionless). Default 2.5 (chosen): the
/// nearest neighbour then usually lies within one cell, so it is found among
/// the cell and its neighbours, while a cell pair holds few pairs to check.
const FISH_PER_NND_CELL: f32 = 2.5;

/// The 13 cell offsets of a half shell: with the cell itself, visiting these
/// from every cell meets every pair of neighbouring cells exactly once.
const HALF_SHELL: [IVec3; 13] = [
    IVec3::new(1, 0, 0),
    IVec3::new(-1, 1, 0),
    IVec3::new(0, 1, 0),
    IVec3::new(1, 1, 0),
    IVec3::new(-1, -1, 1),
    IVec3::new(0, -1, 1),
    IVec3::new(1, -1, 1),
    IVec3::new(-1, 0, 1),
    IVec3::new(0, 0, 1),
    IVec3::new(1, 0, 1),
    IVec3::new(-1, 1, 1),
    IVec3::new(0, 1, 1),
    IVec3::new(1, 1, 1),
];

/// Measures [`SchoolMetrics`] every step without allocating: keeps its grid and
/// buffers. Cost O(N) plus a few operations per occupied grid cell; see
/// [`SchoolMeter::measure`].
#[derive(Clone, Debug, Default)]
pub struct SchoolMeter {
    /// Cells of a diagonal just under the shortest link (for the groups).
    grid: SpatialGrid,
    /// Cells sized to the crowding (for the nearest neighbours).
    nnd_grid: SpatialGrid,
    positions_m: Vec<Vec3>,
    /// Body length of the fish in each slot of `grid`.
    slot_lengths_m: Vec<f32>,
    /// Union-find parent of each slot of `grid`.
    parent: Vec<u32>,
    /// Squared distance to the nearest neighbour found so far, per slot of
    /// `nnd_grid`.
    nearest_sq_m2: Vec<f32>,
    /// Occupied cells grouped by block: `block_cells[block_start[b]..block_start[b + 1]]`.
    block_start: Vec<u32>,
    block_cells: Vec<IVec3>,
    /// Is every fish of the block known to be in one group?
    block_united: Vec<bool>,
    /// Per group root (a slot of `grid`): position sum and count, then the sum
    /// of r̂ × v̂ about the group's centre.
    group_sums: Vec<(Vec3, u32)>,
    /// Each fish's nearest-neighbour distance in its body lengths, by fish.
    nnd_of_fish: Vec<f32>,
    /// Sum of the nearest-neighbour distances (body lengths) per group root.
    group_nnd: Vec<f32>,
    group_turn: Vec<Vec3>,
}

impl SchoolMeter {
    /// The metrics of `fish` in the tank `tank_min_m..tank_max_m`.
    ///
    /// Polarization, milling and mean speed: one pass over the fish.
    ///
    /// Groups (fish linked by gaps of at most [`GROUP_LINK_BODY_LENGTHS`] of
    /// the larger one's length) by union-find over a grid whose cells have a
    /// diagonal just under the shortest possible link, so all fish in one cell
    /// belong to one group (the cell is joined by chaining its fish). Cells
    /// are then joined when any pair of their fish is linked: first each cell
    /// with its face neighbours, then blocks of cells as wide as the longest
    /// link with their 13 forward neighbour blocks (a half shell), skipping
    /// every pair of blocks already known to be one group. A dense school is
    /// one group after the face pass, so 20,000 fish cost a few operations per
    /// cell, not per pair.
    ///
    /// Nearest neighbour: every pair of fish in a cell and its 13 forward
    /// neighbours (each pair once); a fish whose nearest neighbour is farther
    /// than one cell (it may lie beyond those cells) searches ring by ring
    /// ([`SpatialGrid::k_nearest`]). Exact in every case.
    pub fn measure(&mut self, fish: &[Fish], tank_min_m: Vec3, tank_max_m: Vec3) -> SchoolMetrics {
        let n = fish.len();
        if n == 0 {
            return SchoolMetrics::default();
        }
        let count = n as f32;
        let order = order_parameters(fish);
        let mut min_length = f32::INFINITY;
        let mut max_length = 0.0_f32;
        self.positions_m.clear();
        for f in fish {
            min_length = min_length.min(f.body_length_m);
            max_length = max_length.max(f.body_length_m);
            self.positions_m.push(f.position_m);
        }
        let groups = self.count_groups(fish, min_length, max_length, tank_min_m, tank_max_m);
        self.nnd_of_fish.clear();
        self.nnd_of_fish.resize(n, 0.0);
        let nnd_body_lengths = if n > 1 {
            self.nearest_distance_sum_body_lengths(fish, tank_min_m, tank_max_m) / count
        } else {
            0.0
        };
        let milling = self.group_milling(fish);

        SchoolMetrics {
            nnd_body_lengths,
            groups,
            milling,
            ..order
        }
    }

    /// Milling about each group's own centre (see the module doc), from the
    /// groups the last [`Self::count_groups`] found.
    fn group_milling(&mut self, fish: &[Fish]) -> f32 {
        let n = fish.len();
        if n == 0 {
            return 0.0;
        }
        self.group_sums.clear();
        self.group_sums.resize(n, (Vec3::ZERO, 0));
        self.group_nnd.clear();
        self.group_nnd.resize(n, 0.0);
        for slot in 0..n {
            let r = root(&mut self.parent, slot);
            let i = self.grid.slots()[slot] as usize;
            self.group_sums[r].0 += fish[i].position_m;
            self.group_sums[r].1 += 1;
            self.group_nnd[r] += self.nnd_of_fish[i];
        }
        self.group_turn.clear();
        self.group_turn.resize(n, Vec3::ZERO);
        for slot in 0..n {
            let r = root(&mut self.parent, slot);
            let f = &fish[self.grid.slots()[slot] as usize];
            let (sum, count) = self.group_sums[r];
            if (count as usize) < MIN_MILLING_GROUP {
                continue;
            }
            let centre = sum / count as f32;
            self.group_turn[r] += (f.position_m - centre)
                .normalize_or_zero()
                .cross(f.velocity_m_per_s.normalize_or_zero());
        }
        let mut circling = 0.0_f32;
        for ((turn, &(_, count)), &nnd_sum) in self
            .group_turn
            .iter()
            .zip(&self.group_sums)
            .zip(&self.group_nnd)
        {
            let school = nnd_sum <= MILLING_SCHOOL_NND_BODY_LENGTHS * count as f32;
            if (count as usize) >= MIN_MILLING_GROUP && school {
                circling += count as f32 * beyond_chance(turn.length() / count as f32, count);
            }
        }
        (circling / n as f32).min(1.0)
    }

    /// Number of groups (see [`SchoolMeter::measure`]).
    fn count_groups(
        &mut self,
        fish: &[Fish],
        min_length_m: f32,
        max_length_m: f32,
        tank_min_m: Vec3,
        tank_max_m: Vec3,
    ) -> u32 {
        let n = fish.len();
        let min_length_m = min_length_m.max(1e-3);
        let max_length_m = max_length_m.max(min_length_m);
        let link_min_m = GROUP_LINK_BODY_LENGTHS * min_length_m;
        let link_max_m = GROUP_LINK_BODY_LENGTHS * max_length_m;
        // Cube diagonal just under the shortest link.
        let cell_m = link_min_m / 3f32.sqrt() * 0.999;
        self.grid
            .rebuild(tank_min_m, tank_max_m, cell_m, &self.positions_m);
        self.slot_lengths_m.clear();
        self.slot_lengths_m.extend(
            self.grid
                .slots()
                .iter()
                .map(|&i| fish[i as usize].body_length_m),
        );
        // The grid may have had to use bigger cells (a huge tank or tiny
        // fish): then fish sharing a cell are not necessarily linked.
        let cells_are_groups = self.grid.cell_m() <= cell_m * 1.0001;
        self.parent.clear();
        self.parent.extend(0..n as u32);
        self.join_cells_and_faces(cells_are_groups);
        self.join_blocks(cells_are_groups, link_max_m);
        (0..n).filter(|&s| root(&mut self.parent, s) == s).count() as u32
    }

    /// Joins the fish of each cell into one group (when cells are groups:
    /// chained to the cell's first fish; otherwise pair by pair), and each
    /// cell with its +x, +y and +z neighbours when a pair of their fish is
    /// linked.
    fn join_cells_and_faces(&mut self, cells_are_groups: bool) {
        let dims = self.grid.dims();
        for z in 0..dims.z {
            for y in 0..dims.y {
                for x in 0..dims.x {
                    let c = IVec3::new(x, y, z);
                    let here = self.grid.cell_slots(c);
                    if here.is_empty() {
                        continue;
                    }
                    if !cells_are_groups {
                        for a in here.clone() {
                            for b in a + 1..here.end {
                                if self.linked_slots(a, b) {
                                    union(&mut self.parent, a, b);
                                }
                            }
                        }
                        continue;
                    }
                    for s in here.start + 1..here.end {
                        self.parent[s] = here.start as u32;
                    }
                    for face in [IVec3::X, IVec3::Y, IVec3::Z] {
                        let there = self.grid.cell_slots(c + face);
                        if there.is_empty() {
                            continue;
                        }
                        let (ra, rb) = (
                            root(&mut self.parent, here.start),
                            root(&mut self.parent, there.start),
                        );
                        if ra != rb && self.any_link(here.clone(), there) {
                            self.parent[ra.max(rb)] = ra.min(rb) as u32;
                        }
                    }
                }
            }
        }
    }

    /// Sum over the fish of the distance to the nearest other fish, in the
    /// fish's own body lengths.
    fn nearest_distance_sum_body_lengths(
        &mut self,
        fish: &[Fish],
        tank_min_m: Vec3,
        tank_max_m: Vec3,
    ) -> f32 {
        let n = fish.len();
        // Cells sized so that about FISH_PER_NND_CELL fish share one, judged
        // from the group grid's crowding.
        let crowding = self.grid.crowding().max(1.0);
        let cell_m = self.grid.cell_m() * fmath::cbrt(FISH_PER_NND_CELL / crowding);
        self.nnd_grid
            .rebuild(tank_min_m, tank_max_m, cell_m, &self.positions_m);
        let grid = &self.nnd_grid;
        let positions = grid.slot_positions_m();
        let nearest = &mut self.nearest_sq_m2;
        nearest.clear();
        nearest.resize(n, f32::INFINITY);
        // Every pair of fish in a cell, or in a cell and one of its 13
        // forward neighbours, once.
        let dims = grid.dims();
        for z in 0..dims.z {
            for y in 0..dims.y {
                for x in 0..dims.x {
                    let c = IVec3::new(x, y, z);
                    let here = grid.cell_slots(c);
                    if here.is_empty() {
                        continue;
                    }
                    for a in here.clone() {
                        for b in a + 1..here.end {
                            let d2 = positions[a].distance_squared(positions[b]);
                            nearest[a] = nearest[a].min(d2);
                            nearest[b] = nearest[b].min(d2);
                        }
                    }
                    for offset in HALF_SHELL {
                        let there = grid.cell_slots(c + offset);
                        for a in here.clone() {
                            let pa = positions[a];
                            let mut best = nearest[a];
                            for b in there.clone() {
                                let d2 = pa.distance_squared(positions[b]);
                                best = best.min(d2);
                                nearest[b] = nearest[b].min(d2);
                            }
                            nearest[a] = best;
                        }
                    }
                }
            }
        }
        // A nearest neighbour farther than a cell may lie beyond the cells
        // searched: look again, ring by ring.
        let certain_sq_m2 = grid.cell_m() * grid.cell_m();
        let far_m = (tank_max_m - tank_min_m).length() * 2.0 + 1.0;
        let grid_max_m = tank_min_m + dims.as_vec3() * grid.cell_m();
        let mut sum = 0.0_f32;
        for slot in 0..n {
            let p = positions[slot];
            let me = grid.slots()[slot] as usize;
            let mut d2 = nearest[slot];
            let inside = p.cmpge(tank_min_m).all() && p.cmple(grid_max_m).all();
            if d2 > certain_sq_m2 || !inside {
                let mut found = Nearest::new(1);
                grid.k_nearest(p, far_m, &mut found, |j, _, _| j != me);
                d2 = found.iter().next().map_or(d2, |(_, d2)| d2);
            }
            let body_lengths = d2.sqrt() / fish[me].body_length_m.max(1e-3);
            self.nnd_of_fish[me] = body_lengths;
            sum += body_lengths;
        }
        sum
    }

    /// Are the fish in slots `a` and `b` of `grid` linked?
    fn linked_slots(&self, a: usize, b: usize) -> bool {
        let reach_m = GROUP_LINK_BODY_LENGTHS * self.slot_lengths_m[a].max(self.slot_lengths_m[b]);
        let positions = self.grid.slot_positions_m();
        positions[a].distance_squared(positions[b]) <= reach_m * reach_m
    }

    /// Joins linked cells of the same or neighbouring blocks (cubes of cells
    /// at least as wide as the longest link, so linked fish are never more
    /// than one block apart).
    fn join_blocks(&mut self, cells_are_groups: bool, link_max_m: f32) {
        let dims = self.grid.dims();
        let cell_m = self.grid.cell_m();
        let k = ((link_max_m / cell_m).ceil() as i32).max(1);
        let block_dims = (dims + IVec3::splat(k - 1)) / k;
        let blocks = (block_dims.x * block_dims.y * block_dims.z) as usize;
        let block_index = |b: IVec3| (b.x + block_dims.x * (b.y + block_dims.y * b.z)) as usize;
        // Occupied cells, grouped by block (a counting sort).
        self.block_start.clear();
        self.block_start.resize(blocks + 1, 0);
        self.block_cells.clear();
        for pass in 0..2 {
            for z in 0..dims.z {
                for y in 0..dims.y {
                    for x in 0..dims.x {
                        let c = IVec3::new(x, y, z);
                        if self.grid.cell_slots(c).is_empty() {
                            continue;
                        }
                        let b = block_index(c / k);
                        if pass == 0 {
                            self.block_start[b + 1] += 1;
                        } else {
                            let slot = &mut self.block_start[b];
                            self.block_cells[*slot as usize] = c;
                            *slot += 1;
                        }
                    }
                }
            }
            if pass == 0 {
                for b in 0..blocks {
                    self.block_start[b + 1] += self.block_start[b];
                }
                self.block_cells
                    .resize(self.block_start[blocks] as usize, IVec3::ZERO);
            } else {
                // Filling advanced each start to the next block's: shift back.
                for b in (0..blocks).rev() {
                    self.block_start[b + 1] = self.block_start[b];
                }
                self.block_start[0] = 0;
            }
        }
        self.block_united.clear();
        self.block_united.resize(blocks, false);

        let link_cells_sq_m2 = link_max_m * link_max_m;
        for bz in 0..block_dims.z {
            for by in 0..block_dims.y {
                for bx in 0..block_dims.x {
                    let p = IVec3::new(bx, by, bz);
                    if self.block_cell_range(block_index(p)).is_empty() {
                        continue;
                    }
                    for offset in std::iter::once(IVec3::ZERO).chain(HALF_SHELL) {
                        let q = p + offset;
                        if q.cmplt(IVec3::ZERO).any() || q.cmpge(block_dims).any() {
                            continue;
                        }
                        let (bp, bq) = (block_index(p), block_index(q));
                        if self.block_cell_range(bq).is_empty() {
                            continue;
                        }
                        if cells_are_groups {
                            self.join_block_pair(bp, bq, link_cells_sq_m2);
                        } else {
                            self.link_all_pairs(bp, bq, link_cells_sq_m2);
                        }
                    }
                }
            }
        }
    }

    fn block_cell_range(&self, b: usize) -> std::ops::Range<usize> {
        self.block_start[b] as usize..self.block_start[b + 1] as usize
    }

    /// The group of every fish of block `b`, if they are all in one.
    fn united_root(&mut self, b: usize) -> Option<usize> {
        let cells = self.block_cell_range(b);
        let first = self.grid.cell_slots(self.block_cells[cells.start]).start;
        let r = root(&mut self.parent, first);
        if !self.block_united[b] {
            for &c in &self.block_cells[cells] {
                let s = self.grid.cell_slots(c).start;
                if root(&mut self.parent, s) != r {
                    return None;
                }
            }
            // Once united, always united: unions only merge groups.
            self.block_united[b] = true;
        }
        Some(r)
    }

    /// Joins the cells of blocks `bp` and `bq` (the same block or neighbours)
    /// that hold a linked pair of fish; each cell is one group already.
    fn join_block_pair(&mut self, bp: usize, bq: usize, max_link_sq_m2: f32) {
        let (up, uq) = (self.united_root(bp), self.united_root(bq));
        if up.is_some() && (bp == bq || up == uq) {
            return;
        }
        let (cells_p, cells_q) = (self.block_cell_range(bp), self.block_cell_range(bq));
        for ia in cells_p.clone() {
            let first_b = if bp == bq { ia + 1 } else { cells_q.start };
            for ib in first_b..cells_q.end {
                let (a, b) = (self.block_cells[ia], self.block_cells[ib]);
                if box_gap_sq(a, b) * fmath::powi(self.grid.cell_m(), 2) > max_link_sq_m2 {
                    continue;
                }
                let (sa, sb) = (self.grid.cell_slots(a), self.grid.cell_slots(b));
                let (ra, rb) = (
                    root(&mut self.parent, sa.start),
                    root(&mut self.parent, sb.start),
                );
                if ra != rb && self.any_link(sa, sb) {
                    self.parent[ra.max(rb)] = ra.min(rb) as u32;
                }
            }
        }
    }

    /// Is any fish of `a` linked to any fish of `b` (slot ranges)?
    fn any_link(&self, a: std::ops::Range<usize>, b: std::ops::Range<usize>) -> bool {
        a.into_iter()
            .any(|i| b.clone().any(|j| self.linked_slots(i, j)))
    }

    /// Fallback when cells are not groups: links every linked pair of fish in
    /// blocks `bp` and `bq` (pairs within one cell were linked already).
    fn link_all_pairs(&mut self, bp: usize, bq: usize, max_link_sq_m2: f32) {
        let (cells_p, cells_q) = (self.block_cell_range(bp), self.block_cell_range(bq));
        for ia in cells_p {
            let first_b = if bp == bq { ia + 1 } else { cells_q.start };
            for ib in first_b..cells_q.end {
                let (a, b) = (self.block_cells[ia], self.block_cells[ib]);
                if box_gap_sq(a, b) * fmath::powi(self.grid.cell_m(), 2) > max_link_sq_m2 {
                    continue;
                }
                for i in self.grid.cell_slots(a) {
                    for j in self.grid.cell_slots(b) {
                        if self.linked_slots(i, j) {
                            union(&mut self.parent, i, j);
                        }
                    }
                }
            }
        }
    }
}

/// Polarization, milling about the centre of all `fish` (treated as one
/// group) and mean speed (one pass, O(N)); the nearest-neighbour distance and
/// groups are left at zero. [`SchoolMeter::measure`] measures milling per group.
pub fn order_parameters(fish: &[Fish]) -> SchoolMetrics {
    if fish.is_empty() {
        return SchoolMetrics::default();
    }
    let count = fish.len() as f32;
    let mut heading_sum = Vec3::ZERO;
    let mut center = Vec3::ZERO;
    let mut speed_sum = 0.0_f32;
    for f in fish {
        heading_sum += f.velocity_m_per_s.normalize_or_zero();
        center += f.position_m;
        speed_sum += f.speed_m_per_s();
    }
    center /= count;
    let polarization = (heading_sum.length() / count).min(1.0);
    let milling = (fish
        .iter()
        .map(|f| {
            (f.position_m - center)
                .normalize_or_zero()
                .cross(f.velocity_m_per_s.normalize_or_zero())
        })
        .sum::<Vec3>()
        .length()
        / count)
        .min(1.0);
    SchoolMetrics {
        polarization,
        milling,
        nnd_body_lengths: 0.0,
        groups: 0,
        mean_speed_m_per_s: speed_sum / count,
    }
}

/// The squared gap between cells `a` and `b`, in cells: Σ max(|Δ| − 1, 0)².
fn box_gap_sq(a: IVec3, b: IVec3) -> f32 {
    let gap = ((a - b).abs() - IVec3::ONE).max(IVec3::ZERO).as_vec3();
    gap.length_squared()
}

/// Which group each fish belongs to (the groups of [`SchoolMetrics::groups`]:
/// fish linked by gaps of at most [`GROUP_LINK_BODY_LENGTHS`]), as the lowest
/// index in its group. A brute-force O(N²) pass, for small schools (the
/// reef's prey; [`SchoolMeter`] counts the groups of thousands).
pub fn group_labels(fish: &[Fish]) -> Vec<usize> {
    let positions_m: Vec<Vec3> = fish.iter().map(|f| f.position_m).collect();
    let mut parent: Vec<u32> = (0..fish.len() as u32).collect();
    for i in 0..fish.len() {
        for j in i + 1..fish.len() {
            if linked(fish, &positions_m, i, j) {
                union(&mut parent, i, j);
            }
        }
    }
    (0..fish.len()).map(|i| root(&mut parent, i)).collect()
}

/// Are fish `i` and `j` within [`GROUP_LINK_BODY_LENGTHS`] of the larger one's
/// body length?
fn linked(fish: &[Fish], positions_m: &[Vec3], i: usize, j: usize) -> bool {
    let reach_m = GROUP_LINK_BODY_LENGTHS * fish[i].body_length_m.max(fish[j].body_length_m);
    positions_m[i].distance_squared(positions_m[j]) <= reach_m * reach_m
}

/// Joins the groups of `a` and `b` (the smaller root becomes the parent, so
/// the result does not depend on the order of unions).
fn union(parent: &mut [u32], a: usize, b: usize) {
    let (ra, rb) = (root(parent, a), root(parent, b));
    if ra != rb {
        parent[ra.max(rb)] = ra.min(rb) as u32;
    }
}

/// Union-find root with path halving.
fn root(parent: &mut [u32], mut i: usize) -> usize {
    while parent[i] as usize != i {
        let grand = parent[parent[i] as usize];
        parent[i] = grand;
        i = grand as usize;
    }
    i
}

#[cfg(test)]
mod tests {
    use crate::sim::common::school_metrics::*;

    const LO: Vec3 = Vec3::new(-6.0, 0.0, -4.0);
    const HI: Vec3 = Vec3::new(6.0, 4.5, 4.0);

    fn fish_at(position: Vec3, velocity: Vec3) -> Fish {
        Fish::new(position, velocity, 0.4, 0.0)
    }

    fn metrics(fish: &[Fish]) -> SchoolMetrics {
        measure(fish, LO, HI)
    }

    #[test]
    fn a_parallel_school_is_fully_polarised_and_does_not_mill() {
        let school: Vec<Fish> = (0..25)
            .map(|i| {
                fish_at(
                    Vec3::new((i % 5) as f32 * 0.4, 2.0, (i / 5) as f32 * 0.4),
                    Vec3::X * 0.5,
                )
            })
            .collect();
        let m = metrics(&school);
        assert!((m.polarization - 1.0).abs() < 1e-5);
        assert!(m.milling < 0.3);
        assert_eq!(m.groups, 1);
        // Lattice spacing 0.4 m = one body length.
        assert!(
            (m.nnd_body_lengths - 1.0).abs() < 1e-4,
            "{}",
            m.nnd_body_lengths
        );
        assert!((m.mean_speed_m_per_s - 0.5).abs() < 1e-5);
    }

    #[test]
    fn a_mill_has_high_milling_and_low_polarisation() {
        let mill: Vec<Fish> = (0..36)
            .map(|i| {
                let a = i as f32 / 36.0 * std::f32::consts::TAU;
                let radial = Vec3::new(fmath::cos(a), 0.0, fmath::sin(a));
                fish_at(
                    Vec3::new(0.0, 2.0, 0.0) + radial * 1.5,
                    Vec3::Y.cross(radial) * 0.5,
                )
            })
            .collect();
        let m = metrics(&mill);
        assert!(m.milling > 0.99, "{}", m.milling);
        assert!(m.polarization < 0.05, "{}", m.polarization);
    }

    #[test]
    fn milling_is_measured_about_each_group_and_loners_passing_do_not_mill() {
        // Two mills of 12 fish, far apart and turning opposite ways: about the
        // tank's centre their turns cancel; about their own centres both mill.
        let ring = |centre: Vec3, sense: f32| -> Vec<Fish> {
            (0..12)
                .map(|i| {
                    let a = i as f32 / 12.0 * std::f32::consts::TAU;
                    let radial = Vec3::new(fmath::cos(a), 0.0, fmath::sin(a));
                    fish_at(centre + radial * 0.5, Vec3::Y.cross(radial) * 0.5 * sense)
                })
                .collect()
        };
        let mut two_mills = ring(Vec3::new(-3.0, 2.0, 0.0), 1.0);
        two_mills.extend(ring(Vec3::new(3.0, 2.0, 0.0), -1.0));
        assert!(
            metrics(&two_mills).milling > 0.95,
            "{:?}",
            metrics(&two_mills)
        );
        assert!(order_parameters(&two_mills).milling < 0.5);
        // Two fish passing each other head-on, side by side.
        let passing = [
            fish_at(Vec3::new(0.0, 2.0, 0.2), Vec3::X * 0.5),
            fish_at(Vec3::new(0.0, 2.0, -0.2), -Vec3::X * 0.5),
        ];
        assert_eq!(metrics(&passing).milling, 0.0);
    }

    #[test]
    fn a_dense_cluster_with_random_headings_does_not_mill() {
        // 64 fish on a 4×4×4 lattice 0.3 m apart (0.75 body lengths), headings
        // from a fixed scramble: one group, a school by spacing, but no mill.
        // Without the chance rule the turning about its centre reads
        // about 0.75/√64 ≈ 0.1 from the headings alone.
        let mut state = 7_u32;
        let mut signed = || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (state >> 8) as f32 / (1 << 23) as f32 - 1.0
        };
        let mut fish = Vec::new();
        for x in 0..4 {
            for y in 0..4 {
                for z in 0..4 {
                    let p =
                        Vec3::new(x as f32, y as f32, z as f32) * 0.3 + Vec3::new(0.0, 1.0, 0.0);
                    let v = Vec3::new(signed(), signed(), signed()).normalize_or_zero();
                    fish.push(fish_at(p, v * 0.5));
                }
            }
        }
        let m = metrics(&fish);
        assert_eq!(m.groups, 1);
        assert!(m.milling < 0.05, "{m:?}");
    }

    #[test]
    fn a_loose_cloud_sweeping_round_the_tank_is_not_a_mill() {
        // 40 fish on a ring of radius 3 m, 0.47 m apart (1.2 body lengths:
        // linked into one group), all going round the same way. Every other
        // fish is 1.2 body lengths from its nearest neighbour in the ring; the
        // group is a mill when tight, not when its fish are 1.6 body lengths
        // apart on average.
        let ring = |radius: f32| -> Vec<Fish> {
            (0..40)
                .map(|i| {
                    let a = i as f32 / 40.0 * std::f32::consts::TAU;
                    let radial = Vec3::new(fmath::cos(a), 0.0, fmath::sin(a));
                    fish_at(
                        Vec3::new(0.0, 2.0, 0.0) + radial * radius,
                        Vec3::Y.cross(radial) * 0.5,
                    )
                })
                .collect()
        };
        // Neighbours 2π·1.9/40 = 0.30 m apart (0.75 body lengths): a mill.
        let tight = metrics(&ring(1.9));
        assert_eq!(tight.groups, 1);
        assert!(tight.milling > 0.95, "{tight:?}");
        // 2π·3.9/40 = 0.61 m apart (1.53 body lengths, still linked at 2): a
        // loose cloud of loners going round, not a mill.
        let loose = metrics(&ring(3.9));
        assert_eq!(loose.groups, 1, "{loose:?}");
        assert!(loose.nnd_body_lengths > MILLING_SCHOOL_NND_BODY_LENGTHS);
        assert_eq!(loose.milling, 0.0, "{loose:?}");
    }

    #[test]
    fn separated_clusters_count_as_groups() {
        let mut fish = Vec::new();
        for (cx, count) in [(-4.0, 5), (0.0, 3), (4.0, 1)] {
            for k in 0..count {
                fish.push(fish_at(Vec3::new(cx + k as f32 * 0.5, 2.0, 0.0), Vec3::Z));
            }
        }
        assert_eq!(metrics(&fish).groups, 3);
        // The lone fish's nearest neighbour is far: the mean distance grows.
        assert!(metrics(&fish).nnd_body_lengths > 1.25);
    }

    #[test]
    fn empty_single_and_still_fish_give_finite_metrics() {
        assert_eq!(metrics(&[]), SchoolMetrics::default());
        let one = metrics(&[fish_at(Vec3::ONE, Vec3::ZERO)]);
        assert_eq!(one.groups, 1);
        assert_eq!(one.nnd_body_lengths, 0.0);
        let still = metrics(&[
            fish_at(Vec3::ONE, Vec3::ZERO),
            fish_at(Vec3::ONE, Vec3::ZERO),
        ]);
        assert!(still.polarization.is_finite() && still.milling.is_finite());
    }

    #[test]
    fn groups_and_nearest_distance_match_a_brute_force_count() {
        // Pseudo-random fish of mixed sizes; compare with all pairs.
        let mut s = 17u64;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 40) as f32 / (1u64 << 24) as f32
        };
        let fish: Vec<Fish> = (0..400)
            .map(|_| {
                Fish::new(
                    Vec3::new(next() * 12.0 - 6.0, next() * 4.5, next() * 8.0 - 4.0),
                    Vec3::X,
                    0.3 + 0.2 * next(),
                    0.0,
                )
            })
            .collect();
        let n = fish.len();
        let positions: Vec<Vec3> = fish.iter().map(|f| f.position_m).collect();
        let mut nnd = 0.0;
        for i in 0..n {
            let mut best = f32::INFINITY;
            for j in 0..n {
                if i != j {
                    best = best.min(positions[i].distance(positions[j]));
                }
            }
            nnd += best / fish[i].body_length_m;
        }
        // `group_labels` links all pairs.
        let labels = group_labels(&fish);
        let groups = (0..n).filter(|&i| labels[i] == i).count() as u32;
        let m = metrics(&fish);
        assert_eq!(m.groups, groups);
        assert!((m.nnd_body_lengths - nnd / n as f32).abs() < 1e-4);
    }
}
