//! A uniform grid over the tank for neighbour queries, so finding a fish's
//! neighbours costs O(neighbours) instead of O(N): never all pairs.
//!
//! Rebuilt from scratch whenever positions change (a counting sort into cells,
//! O(N), no allocation once the buffers have grown). Cells are cubes of side
//! `cell_m`; a query of radius r ≤ `cell_m` visits the 27 cells around a point.

use glam::{IVec3, Vec3};

/// Fish indices bucketed by grid cell.
#[derive(Clone, Debug, Default)]
pub struct SpatialGrid {
    origin_m: Vec3,
    cell_m: f32,
    dims: IVec3,
    /// `cell_start[c]..cell_start[c + 1]` indexes `sorted` for cell `c`.
    cell_start: Vec<u32>,
    sorted: Vec<u32>,
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
        // Bound the cell count (at most 64³) whatever the radius asked for.
        let cell_m = cell_m.max(extent.max_element() / 64.0);
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
        // Fill each cell back to front, counting its start down; afterwards
        // `cell_start[c]` is the cell's first slot again (no extra buffer).
        for c in 0..cells {
            self.cell_start[c] = self.cell_start[c + 1];
        }
        for (i, &c) in self.cell_of.iter().enumerate().rev() {
            let slot = &mut self.cell_start[c as usize];
            *slot -= 1;
            self.sorted[*slot as usize] = i as u32;
        }
    }

    /// Side of a cell in metres (may be larger than asked, see `rebuild`).
    pub fn cell_m(&self) -> f32 {
        self.cell_m
    }

    fn cell_coords(&self, p: Vec3) -> IVec3 {
        let q = ((p - self.origin_m) / self.cell_m).floor();
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
        let lo = (center - IVec3::splat(reach)).max(IVec3::ZERO);
        let hi = (center + IVec3::splat(reach)).min(self.dims - IVec3::ONE);
        for z in lo.z..=hi.z {
            for y in lo.y..=hi.y {
                for x in lo.x..=hi.x {
                    let c = self.cell_index(IVec3::new(x, y, z));
                    let (start, end) =
                        (self.cell_start[c] as usize, self.cell_start[c + 1] as usize);
                    for &j in &self.sorted[start..end] {
                        visit(j as usize);
                    }
                }
            }
        }
    }
}

/// Most neighbours a [`Nearest`] list can hold. Default 16: twice the 6–7
/// neighbours starlings interact with (Ballerini et al. 2008), room for tuning.
pub const MAX_NEAREST: usize = 16;

/// Up to `k` (≤ [`MAX_NEAREST`]) nearest accepted points, nearest first: a small
/// sorted array, so a query allocates nothing.
#[derive(Clone, Copy, Debug)]
pub struct Nearest {
    k: usize,
    len: usize,
    index: [u32; MAX_NEAREST],
    distance_sq_m2: [f32; MAX_NEAREST],
}

impl Nearest {
    /// An empty list that keeps the `k` nearest (at most [`MAX_NEAREST`]).
    pub fn new(k: usize) -> Self {
        Self {
            k: k.min(MAX_NEAREST),
            len: 0,
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
    }

    /// Is the list full (`k` points kept)?
    pub fn is_full(&self) -> bool {
        self.len == self.k
    }

    /// Squared distance of the farthest kept point, or infinity when not full.
    pub fn bound_sq_m2(&self) -> f32 {
        if self.is_full() && self.k > 0 {
            self.distance_sq_m2[self.k - 1]
        } else {
            f32::INFINITY
        }
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
    /// for which `accept(j, distance_sq_m2)` is true, found by visiting cells in
    /// rings (shells of cells) of growing distance around `p`'s cell and
    /// stopping as soon as no unvisited cell can hold a nearer point. Costs
    /// about the cells and points within the k-th distance, not within
    /// `max_radius_m`: the search for 7 neighbours in a dense school stays
    /// local however far the fish can see.
    pub fn k_nearest(
        &self,
        p: Vec3,
        positions_m: &[Vec3],
        max_radius_m: f32,
        nearest: &mut Nearest,
        mut accept: impl FnMut(usize, f32) -> bool,
    ) {
        if self.sorted.is_empty() || !p.is_finite() {
            return;
        }
        let max_radius_sq_m2 = max_radius_m * max_radius_m;
        let center = self.cell_coords(p);
        let max_ring = ((max_radius_m.max(0.0) / self.cell_m).ceil() as i32)
            .min(self.dims.max_element())
            .max(0);
        for ring in 0..=max_ring {
            let lo = center - IVec3::splat(ring);
            let hi = center + IVec3::splat(ring);
            for z in lo.z.max(0)..=hi.z.min(self.dims.z - 1) {
                let z_on_shell = z == lo.z || z == hi.z;
                for y in lo.y.max(0)..=hi.y.min(self.dims.y - 1) {
                    let on_shell = z_on_shell || y == lo.y || y == hi.y;
                    let step = if on_shell { 1 } else { (2 * ring).max(1) };
                    let mut x = lo.x;
                    while x <= hi.x {
                        if x >= 0 && x < self.dims.x {
                            let c = self.cell_index(IVec3::new(x, y, z));
                            let (start, end) =
                                (self.cell_start[c] as usize, self.cell_start[c + 1] as usize);
                            for &j in &self.sorted[start..end] {
                                let j = j as usize;
                                let d2 = positions_m[j].distance_squared(p);
                                if d2 <= max_radius_sq_m2
                                    && d2 < nearest.bound_sq_m2()
                                    && accept(j, d2)
                                {
                                    nearest.offer(j, d2);
                                }
                            }
                        }
                        x += step;
                    }
                }
            }
            // Every point in a farther ring is at least ring·cell away.
            let reach_m = ring as f32 * self.cell_m;
            if nearest.bound_sq_m2() <= reach_m * reach_m {
                break;
            }
        }
    }

    /// The mean number of points per occupied cell as a fish sees it (Σ n² / Σ n): how crowded
    /// the grid is around a typical point, used to size the next grid.
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

    /// Number of cells (including empty ones).
    pub fn cell_count(&self) -> usize {
        self.cell_start.len().saturating_sub(1)
    }

    /// Calls `visit(a, b, points_a, points_b)` once for every unordered pair of
    /// distinct non-empty cells `a < b` whose grid coordinates differ by at most
    /// `reach` on every axis, and `visit(a, a, points_a, points_a)` for every
    /// non-empty cell. Used to find linked groups without visiting all pairs.
    pub fn for_each_cell_pair(
        &self,
        reach: i32,
        mut visit: impl FnMut(usize, usize, &[u32], &[u32]),
    ) {
        let reach = reach.max(0);
        for c in 0..self.cell_count() {
            let (start, end) = (self.cell_start[c] as usize, self.cell_start[c + 1] as usize);
            if start == end {
                continue;
            }
            let a = &self.sorted[start..end];
            visit(c, c, a, a);
            let ci = c as i32;
            let coords = IVec3::new(
                ci % self.dims.x,
                (ci / self.dims.x) % self.dims.y,
                ci / (self.dims.x * self.dims.y),
            );
            let lo = (coords - IVec3::splat(reach)).max(IVec3::ZERO);
            let hi = (coords + IVec3::splat(reach)).min(self.dims - IVec3::ONE);
            for z in lo.z..=hi.z {
                for y in lo.y..=hi.y {
                    for x in lo.x..=hi.x {
                        let d = self.cell_index(IVec3::new(x, y, z));
                        if d <= c {
                            continue;
                        }
                        let (s2, e2) =
                            (self.cell_start[d] as usize, self.cell_start[d + 1] as usize);
                        if s2 < e2 {
                            visit(c, d, a, &self.sorted[s2..e2]);
                        }
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
                    grid.k_nearest(p, &points, radius, &mut nearest, |j, _| {
                        j != i && j % 2 == 0
                    });
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

    #[test]
    fn cell_pairs_cover_every_pair_of_points_within_reach_once() {
        let points = lcg_points(300, 9);
        let mut grid = SpatialGrid::default();
        grid.rebuild(
            Vec3::new(-6.0, 0.0, -4.0),
            Vec3::new(6.0, 4.5, 4.0),
            1.0,
            &points,
        );
        let mut pairs = 0usize;
        grid.for_each_cell_pair(1, |ca, cb, a, b| {
            if ca == cb {
                pairs += a.len() * (a.len() - 1) / 2;
            } else {
                pairs += a.len() * b.len();
            }
        });
        let mut expected = 0usize;
        grid.for_each_candidate(Vec3::ZERO, 0.0, |_| {});
        for (i, &p) in points.iter().enumerate() {
            let mut count = 0;
            grid.for_each_candidate(p, 1.0, |j| count += usize::from(j != i));
            expected += count;
        }
        assert_eq!(pairs * 2, expected);
    }
}
