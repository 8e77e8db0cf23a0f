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
        let mut fill = self.cell_start.clone();
        for (i, &c) in self.cell_of.iter().enumerate() {
            let slot = &mut fill[c as usize];
            self.sorted[*slot as usize] = i as u32;
            *slot += 1;
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
}
