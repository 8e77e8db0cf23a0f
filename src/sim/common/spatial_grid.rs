//! A uniform grid over the tank for neighbour queries, so finding a fish's
//! neighbours costs O(neighbours) instead of O(N): never all pairs.
//!
//! Rebuilt from scratch whenever positions change (a counting sort into cells,
//! O(N), no allocation once the buffers have grown). Cells are cubes of side
//! `cell_m`, numbered with x fastest, so a row of cells along x is one
//! contiguous run of slots. The grid keeps its own copy of the positions in
//! slot order (structure of arrays), so a query scans memory front to back
//! instead of jumping around the fish list.

use glam::{IVec3, Vec3, Vec4};

/// Most cells along one axis. Default 64 (at most 64³ ≈ 262,000 cells):
/// bounds the memory whatever cell size is asked for.
const MAX_CELLS_PER_AXIS: f32 = 64.0;

/// Points bucketed by grid cell.
#[derive(Clone, Debug, Default)]
pub struct SpatialGrid {
    origin_m: Vec3,
    cell_m: f32,
    dims: IVec3,
    /// `cell_start[c]..cell_start[c + 1]` are the slots of cell `c`.
    cell_start: Vec<u32>,
    /// The point (index into the positions given to `rebuild`) in each slot.
    sorted: Vec<u32>,
    /// The position of the point in each slot.
    sorted_positions_m: Vec<Vec3>,
    /// The same, as structure of arrays (x, y and z apart), so that a query
    /// computes four distances at once.
    sorted_x_m: Vec<f32>,
    sorted_y_m: Vec<f32>,
    sorted_z_m: Vec<f32>,
    cell_of: Vec<u32>,
}

impl SpatialGrid {
    /// Buckets `positions_m` into cubes of side `cell_m` covering `min_m..max_m`
    /// (points outside are clamped into the border cells).
    pub fn rebuild(&mut self, min_m: Vec3, max_m: Vec3, cell_m: f32, positions_m: &[Vec3]) {
        let cell_m = if cell_m.is_finite() && cell_m > 1e-3 {
            cell_m
        } else {
            1.0
        };
        let extent = (max_m - min_m).max(Vec3::splat(cell_m));
        // Bound the cell count whatever the radius asked for.
        let cell_m = cell_m.max(extent.max_element() / MAX_CELLS_PER_AXIS);
        self.origin_m = min_m;
        self.cell_m = cell_m;
        self.dims = (extent / cell_m).ceil().as_ivec3().max(IVec3::ONE);
        let cells = (self.dims.x * self.dims.y * self.dims.z) as usize;
        self.cell_start.clear();
        self.cell_start.resize(cells + 1, 0);
        self.cell_of.clear();
        for &p in positions_m {
            let c = self.cell_index(self.cell_coords(p));
            self.cell_of.push(c as u32);
            self.cell_start[c + 1] += 1;
        }
        for c in 0..cells {
            self.cell_start[c + 1] += self.cell_start[c];
        }
        self.sorted.clear();
        self.sorted.resize(positions_m.len(), 0);
        self.sorted_positions_m.clear();
        self.sorted_positions_m
            .resize(positions_m.len(), Vec3::ZERO);
        // Fill each cell back to front, counting its start down; afterwards
        // `cell_start[c]` is the cell's first slot again (no extra buffer).
        for c in 0..cells {
            self.cell_start[c] = self.cell_start[c + 1];
        }
        for (i, &c) in self.cell_of.iter().enumerate().rev() {
            let slot = &mut self.cell_start[c as usize];
            *slot -= 1;
            self.sorted[*slot as usize] = i as u32;
            self.sorted_positions_m[*slot as usize] = positions_m[i];
        }
        let sorted = &self.sorted_positions_m;
        for (axis, out) in [
            &mut self.sorted_x_m,
            &mut self.sorted_y_m,
            &mut self.sorted_z_m,
        ]
        .into_iter()
        .enumerate()
        {
            out.clear();
            out.extend(sorted.iter().map(|p| p[axis]));
        }
    }

    /// Side of a cell in metres (may be larger than asked, see `rebuild`).
    pub fn cell_m(&self) -> f32 {
        self.cell_m
    }

    /// Number of cells along x, y and z.
    pub fn dims(&self) -> IVec3 {
        self.dims
    }

    /// The points in slot order (cell by cell): `slots()[s]` is the index of
    /// the point in slot `s`.
    pub fn slots(&self) -> &[u32] {
        &self.sorted
    }

    /// The positions in slot order.
    pub fn slot_positions_m(&self) -> &[Vec3] {
        &self.sorted_positions_m
    }

    /// The slots of the cell at grid coordinates `c` (empty outside the grid).
    pub fn cell_slots(&self, c: IVec3) -> std::ops::Range<usize> {
        if c.cmplt(IVec3::ZERO).any() || c.cmpge(self.dims).any() {
            return 0..0;
        }
        let i = self.cell_index(c);
        self.cell_start[i] as usize..self.cell_start[i + 1] as usize
    }

    /// The slots of the cells from `(x_lo, y, z)` to `(x_hi, y, z)` (one
    /// contiguous run; coordinates are clipped to the grid).
    pub fn row_slots(&self, x_lo: i32, x_hi: i32, y: i32, z: i32) -> std::ops::Range<usize> {
        let (x_lo, x_hi) = (x_lo.max(0), x_hi.min(self.dims.x - 1));
        if x_lo > x_hi || y < 0 || z < 0 || y >= self.dims.y || z >= self.dims.z {
            return 0..0;
        }
        let first = self.cell_index(IVec3::new(x_lo, y, z));
        let last = self.cell_index(IVec3::new(x_hi, y, z));
        self.cell_start[first] as usize..self.cell_start[last + 1] as usize
    }

    /// Grid coordinates of the cell holding `p` (clamped into the grid).
    pub fn cell_coords(&self, p: Vec3) -> IVec3 {
        // Truncation rounds negative values up, but those clamp to 0 either
        // way; `floor` would be a slow library call on baseline x86-64.
        let q = (p - self.origin_m) / self.cell_m;
        let q = if q.is_finite() {
            q.as_ivec3()
        } else {
            IVec3::ZERO
        };
        q.clamp(IVec3::ZERO, self.dims - IVec3::ONE)
    }

    fn cell_index(&self, c: IVec3) -> usize {
        (c.x + self.dims.x * (c.y + self.dims.y * c.z)) as usize
    }

    /// Calls `visit(j)` for every indexed point in the cells that can hold points
    /// within `radius_m` of `p` (the caller checks the exact distance). Visits
    /// every cell in range, so any radius works; small radii are fastest.
    pub fn for_each_candidate(&self, p: Vec3, radius_m: f32, mut visit: impl FnMut(usize)) {
        if self.sorted.is_empty() {
            return;
        }
        let reach = (radius_m.max(0.0) / self.cell_m).ceil() as i32;
        let reach = reach.min(self.dims.max_element());
        let center = self.cell_coords(p);
        let lo = center - IVec3::splat(reach);
        let hi = center + IVec3::splat(reach);
        for z in lo.z.max(0)..=hi.z.min(self.dims.z - 1) {
            for y in lo.y.max(0)..=hi.y.min(self.dims.y - 1) {
                for &j in &self.sorted[self.row_slots(lo.x, hi.x, y, z)] {
                    visit(j as usize);
                }
            }
        }
    }
}

/// What visiting one row of cells costs, in points scanned. Default 8
/// (measured roughly: a row's bookkeeping takes as long as checking eight
/// points four at a time). Decides when [`SpatialGrid::k_nearest`] scans all
/// points instead of another shell of cells.
const ROW_COST_IN_POINTS: usize = 8;

/// Most neighbours a [`Nearest`] list can hold. Default 16: twice the 6–7
/// neighbours starlings interact with (Ballerini et al. 2008), room for tuning.
pub const MAX_NEAREST: usize = 16;

/// Up to `k` (≤ [`MAX_NEAREST`]) nearest accepted points, nearest first: a small
/// sorted array, so a query allocates nothing.
#[derive(Clone, Copy, Debug)]
pub struct Nearest {
    k: usize,
    len: usize,
    /// Squared distance of the k-th kept point (infinity until full).
    bound_sq_m2: f32,
    index: [u32; MAX_NEAREST],
    distance_sq_m2: [f32; MAX_NEAREST],
}

impl Nearest {
    /// An empty list that keeps the `k` nearest (at most [`MAX_NEAREST`]).
    pub fn new(k: usize) -> Self {
        Self {
            k: k.min(MAX_NEAREST),
            len: 0,
            bound_sq_m2: if k == 0 { 0.0 } else { f32::INFINITY },
            index: [0; MAX_NEAREST],
            distance_sq_m2: [f32::INFINITY; MAX_NEAREST],
        }
    }

    /// Offers point `j` at squared distance `distance_sq_m2`; kept if among the
    /// `k` nearest so far (ties keep the earlier offer, so results are
    /// deterministic).
    pub fn offer(&mut self, j: usize, distance_sq_m2: f32) {
        if self.k == 0 || (self.len == self.k && distance_sq_m2 >= self.distance_sq_m2[self.k - 1])
        {
            return;
        }
        let mut slot = self.len.min(self.k - 1);
        while slot > 0 && self.distance_sq_m2[slot - 1] > distance_sq_m2 {
            self.index[slot] = self.index[slot - 1];
            self.distance_sq_m2[slot] = self.distance_sq_m2[slot - 1];
            slot -= 1;
        }
        self.index[slot] = j as u32;
        self.distance_sq_m2[slot] = distance_sq_m2;
        self.len = (self.len + 1).min(self.k);
        if self.len == self.k {
            self.bound_sq_m2 = self.distance_sq_m2[self.k - 1];
        }
    }

    /// The same list with every kept point renumbered by `renumber` (order
    /// and distances unchanged).
    pub fn renumbered(mut self, renumber: impl Fn(u32) -> u32) -> Self {
        for j in &mut self.index[..self.len] {
            *j = renumber(*j);
        }
        self
    }

    /// How many points the list keeps at most (`k`).
    pub fn capacity(&self) -> usize {
        self.k
    }

    /// Is point `j` in the list?
    pub fn contains(&self, j: usize) -> bool {
        self.index[..self.len].contains(&(j as u32))
    }

    /// Is the list full (`k` points kept)?
    pub fn is_full(&self) -> bool {
        self.len == self.k
    }

    /// Squared distance of the farthest kept point, or infinity when not full
    /// (zero when `k` is zero: nothing can be kept).
    pub fn bound_sq_m2(&self) -> f32 {
        self.bound_sq_m2
    }

    /// The kept points as (index, squared distance), nearest first.
    pub fn iter(&self) -> impl Iterator<Item = (usize, f32)> + '_ {
        (0..self.len).map(|s| (self.index[s] as usize, self.distance_sq_m2[s]))
    }

    /// How many points are kept.
    pub fn len(&self) -> usize {
        self.len
    }

    /// No point kept?
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

impl SpatialGrid {
    /// The `nearest.k` points nearest to `p` among those within `max_radius_m`
    /// for which `accept(j, position_m, distance_sq_m2)` is true (`j` the
    /// point's index, `position_m` its position), found by visiting cells in
    /// rings (shells of cells) of growing distance around `p`'s cell and
    /// stopping as soon as no unvisited cell can hold a nearer point. Costs
    /// about the cells and points within the k-th distance, not within
    /// `max_radius_m`: the search for 7 neighbours in a dense school stays
    /// local however far the fish can see. Where the next shell of cells would
    /// cost more than scanning every point, it scans every point instead (so
    /// `accept` may be asked about a point twice; it must not have side
    /// effects). Points already in `nearest` (accepted points within
    /// `max_radius_m`, with their squared distances from `p`) are kept unless
    /// nearer ones are found, and never offered twice: a search seeded with
    /// good guesses is pruned from the start and finds the same points.
    pub fn k_nearest(
        &self,
        p: Vec3,
        max_radius_m: f32,
        nearest: &mut Nearest,
        accept: impl FnMut(usize, Vec3, f32) -> bool,
    ) {
        self.k_nearest_in::<false>(p, max_radius_m, nearest, accept);
    }

    /// [`Self::k_nearest`] in slot numbering: `accept` is given, and
    /// `nearest` holds, slots ([`Self::slots`]) instead of the points'
    /// indices. The same points in the same order (the slots are a
    /// renumbering), for callers that keep their data in slot order so that
    /// neighbours lie close together in memory.
    pub fn k_nearest_slots(
        &self,
        p: Vec3,
        max_radius_m: f32,
        nearest: &mut Nearest,
        accept: impl FnMut(usize, Vec3, f32) -> bool,
    ) {
        self.k_nearest_in::<true>(p, max_radius_m, nearest, accept);
    }

    /// [`Self::k_nearest`] (`BY_SLOT` false) or [`Self::k_nearest_slots`].
    fn k_nearest_in<const BY_SLOT: bool>(
        &self,
        p: Vec3,
        max_radius_m: f32,
        nearest: &mut Nearest,
        mut accept: impl FnMut(usize, Vec3, f32) -> bool,
    ) {
        if self.sorted.is_empty() || !p.is_finite() || nearest.k == 0 {
            return;
        }
        let max_radius_sq_m2 = max_radius_m * max_radius_m;
        let center = self.cell_coords(p);
        // Distance from p to the nearest face of its own cell (0 if p lies
        // outside the grid): the block of rings 0..=r reaches at least
        // r·cell plus this far from p in every direction.
        let local = (p - self.origin_m) / self.cell_m - center.as_vec3();
        let margin_m = local.min(Vec3::ONE - local).min_element().max(0.0) * self.cell_m;
        let max_ring = ((max_radius_m.max(0.0) / self.cell_m).ceil() as i32)
            .min(self.dims.max_element())
            .max(0);
        // p in cell units, relative to the grid's origin.
        let p_cells = (p - self.origin_m) / self.cell_m;
        let cell_sq_m2 = self.cell_m * self.cell_m;
        // Squared distance, in cells², from p to the slab of cells `c` along
        // one axis (0 inside it).
        let gap_sq = |coord: f32, c: i32| {
            let gap = (c as f32 - coord).max(coord - (c + 1) as f32).max(0.0);
            gap * gap
        };
        // Scans the cells x_lo..=x_hi of row (y, z), or only the part of it
        // that reaches into the sphere of the current k-th distance.
        let mut scan_row = |x_lo: i32, x_hi: i32, y: i32, z: i32, nearest: &mut Nearest| {
            let bound_cells_sq = nearest.bound_sq_m2 / cell_sq_m2;
            let gap_yz_sq = gap_sq(p_cells.z, z) + gap_sq(p_cells.y, y);
            if gap_yz_sq >= bound_cells_sq {
                return;
            }
            let half_width = (bound_cells_sq - gap_yz_sq).sqrt();
            // (Truncation, not `floor`: it differs only below 0, where there
            // are no cells.)
            let (x_lo, x_hi) = if half_width.is_finite() {
                (
                    ((p_cells.x - half_width) as i32).max(x_lo),
                    ((p_cells.x + half_width) as i32).min(x_hi),
                )
            } else {
                (x_lo, x_hi)
            };
            let slots = self.row_slots(x_lo, x_hi, y, z);
            self.scan::<BY_SLOT>(slots, p, max_radius_sq_m2, nearest, &mut accept);
        };
        // Rings 0 and 1 (the 3×3×3 block) row by row, nearest rows first, so
        // the k-th distance shrinks early and prunes the rest.
        const BLOCK_ROWS: [(i32, i32); 9] = [
            (0, 0),
            (-1, 0),
            (1, 0),
            (0, -1),
            (0, 1),
            (-1, -1),
            (1, -1),
            (-1, 1),
            (1, 1),
        ];
        let first_ring = if max_ring >= 1 {
            for (dy, dz) in BLOCK_ROWS {
                scan_row(
                    center.x - 1,
                    center.x + 1,
                    center.y + dy,
                    center.z + dz,
                    nearest,
                );
            }
            1
        } else {
            scan_row(center.x, center.x, center.y, center.z, nearest);
            0
        };
        let done = |ring: i32, nearest: &Nearest| {
            // Every point in a farther ring is at least this far away.
            let reach_m = ring as f32 * self.cell_m + margin_m;
            nearest.bound_sq_m2 <= reach_m * reach_m
        };
        if done(first_ring, nearest) {
            return;
        }
        for ring in first_ring + 1..=max_ring {
            // A sparse neighbourhood (a straggler far from its school): when
            // a shell has more rows than there are points, scanning every
            // point once is cheaper than visiting the shells. Start afresh.
            let shell_rows = (2 * ring + 1) * (2 * ring + 1);
            if (shell_rows as usize) * ROW_COST_IN_POINTS > self.sorted.len() {
                *nearest = Nearest::new(nearest.k);
                self.scan::<BY_SLOT>(
                    0..self.sorted.len(),
                    p,
                    max_radius_sq_m2,
                    nearest,
                    &mut accept,
                );
                return;
            }
            let lo = center - IVec3::splat(ring);
            let hi = center + IVec3::splat(ring);
            for z in lo.z.max(0)..=hi.z.min(self.dims.z - 1) {
                let z_on_shell = z == lo.z || z == hi.z;
                for y in lo.y.max(0)..=hi.y.min(self.dims.y - 1) {
                    if z_on_shell || y == lo.y || y == hi.y {
                        // A row of the shell.
                        scan_row(lo.x, hi.x, y, z, nearest);
                    } else {
                        // Inside the shell's cross-section: only the two ends.
                        scan_row(lo.x, lo.x, y, z, nearest);
                        scan_row(hi.x, hi.x, y, z, nearest);
                    }
                }
            }
            if done(ring, nearest) {
                return;
            }
        }
    }

    /// Offers to `nearest` the points of `slots` within `max_radius_sq_m2` of
    /// `p` that are nearer than its k-th and that `accept` takes, computing
    /// distances four at a time.
    fn scan<const BY_SLOT: bool>(
        &self,
        slots: std::ops::Range<usize>,
        p: Vec3,
        max_radius_sq_m2: f32,
        nearest: &mut Nearest,
        accept: &mut impl FnMut(usize, Vec3, f32) -> bool,
    ) {
        let xs = &self.sorted_x_m[slots.clone()];
        let ys = &self.sorted_y_m[slots.clone()];
        let zs = &self.sorted_z_m[slots.clone()];
        let mut offer = |k: usize, d2: f32, nearest: &mut Nearest| {
            if d2 <= max_radius_sq_m2 && d2 < nearest.bound_sq_m2 {
                let j = if BY_SLOT {
                    slots.start + k
                } else {
                    self.sorted[slots.start + k] as usize
                };
                if accept(j, Vec3::new(xs[k], ys[k], zs[k]), d2) && !nearest.contains(j) {
                    nearest.offer(j, d2);
                }
            }
        };
        let (px, py, pz) = (Vec4::splat(p.x), Vec4::splat(p.y), Vec4::splat(p.z));
        let mut k = 0;
        while k + 4 <= xs.len() {
            let dx = Vec4::from_slice(&xs[k..k + 4]) - px;
            let dy = Vec4::from_slice(&ys[k..k + 4]) - py;
            let dz = Vec4::from_slice(&zs[k..k + 4]) - pz;
            let d2 = dx * dx + dy * dy + dz * dz;
            let limit = Vec4::splat(nearest.bound_sq_m2.min(max_radius_sq_m2.next_up()));
            let mut hits = d2.cmplt(limit).bitmask();
            while hits != 0 {
                let lane = hits.trailing_zeros() as usize;
                offer(k + lane, d2[lane], nearest);
                hits &= hits - 1;
            }
            k += 4;
        }
        for k in k..xs.len() {
            let d2 = Vec3::new(xs[k], ys[k], zs[k]).distance_squared(p);
            offer(k, d2, nearest);
        }
    }

    /// The mean number of points per occupied cell as a point sees it
    /// (Σ n² / Σ n): how crowded the grid is around a typical point, used to
    /// size the next grid.
    pub fn crowding(&self) -> f32 {
        let cells = self.cell_start.len().saturating_sub(1);
        let mut sum = 0u64;
        let mut sum_sq = 0u64;
        for c in 0..cells {
            let n = u64::from(self.cell_start[c + 1] - self.cell_start[c]);
            sum += n;
            sum_sq += n * n;
        }
        if sum == 0 {
            0.0
        } else {
            sum_sq as f32 / sum as f32
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::common::spatial_grid::*;

    fn lcg_points(n: usize, seed: u64) -> Vec<Vec3> {
        let mut s = seed;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 40) as f32 / (1u64 << 24) as f32
        };
        (0..n)
            .map(|_| Vec3::new(next() * 12.0 - 6.0, next() * 4.5, next() * 8.0 - 4.0))
            .collect()
    }

    #[test]
    fn finds_exactly_the_neighbours_that_brute_force_finds() {
        let points = lcg_points(800, 3);
        let mut grid = SpatialGrid::default();
        for radius in [0.3, 1.0, 2.5] {
            grid.rebuild(
                Vec3::new(-6.0, 0.0, -4.0),
                Vec3::new(6.0, 4.5, 4.0),
                radius,
                &points,
            );
            for (i, &p) in points.iter().enumerate().step_by(7) {
                let mut found = Vec::new();
                grid.for_each_candidate(p, radius, |j| {
                    if j != i && points[j].distance(p) <= radius {
                        found.push(j);
                    }
                });
                found.sort_unstable();
                let expected: Vec<usize> = (0..points.len())
                    .filter(|&j| j != i && points[j].distance(p) <= radius)
                    .collect();
                assert_eq!(found, expected, "radius {radius}, point {i}");
            }
        }
    }

    #[test]
    fn points_outside_the_box_and_nan_do_not_panic() {
        let mut grid = SpatialGrid::default();
        let points = [
            Vec3::splat(100.0),
            Vec3::splat(-100.0),
            Vec3::NAN,
            Vec3::ZERO,
        ];
        grid.rebuild(Vec3::ZERO, Vec3::ONE, 0.0, &points);
        let mut count = 0;
        grid.for_each_candidate(Vec3::ZERO, 10.0, |_| count += 1);
        assert_eq!(count, 4);
        grid.rebuild(Vec3::ZERO, Vec3::ONE, 0.5, &[]);
        grid.for_each_candidate(Vec3::ZERO, 1.0, |_| panic!("empty grid"));
    }

    #[test]
    fn k_nearest_finds_the_same_neighbours_as_sorting_all_distances() {
        let points = lcg_points(2_000, 5);
        let mut grid = SpatialGrid::default();
        for cell_m in [0.2, 0.5, 1.5] {
            grid.rebuild(
                Vec3::new(-6.0, 0.0, -4.0),
                Vec3::new(6.0, 4.5, 4.0),
                cell_m,
                &points,
            );
            for (i, &p) in points.iter().enumerate().step_by(37) {
                for (k, radius) in [(7, 5.0), (1, 5.0), (16, 0.6)] {
                    let mut nearest = Nearest::new(k);
                    // Only even indices are "seen".
                    grid.k_nearest(p, radius, &mut nearest, |j, _, _| j != i && j % 2 == 0);
                    let found: Vec<usize> = nearest.iter().map(|(j, _)| j).collect();
                    let mut all: Vec<(f32, usize)> = (0..points.len())
                        .filter(|&j| j != i && j % 2 == 0 && points[j].distance(p) <= radius)
                        .map(|j| (points[j].distance_squared(p), j))
                        .collect();
                    all.sort_by(|a, b| a.0.total_cmp(&b.0));
                    let expected: Vec<usize> = all.iter().take(k).map(|&(_, j)| j).collect();
                    assert_eq!(found, expected, "cell {cell_m}, point {i}, k {k}");
                }
            }
        }
    }
}
