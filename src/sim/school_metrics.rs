//! Numbers that tell a school from a crowd of loners, computed from the fish's
//! positions and velocities (Couzin et al. 2002's order parameters, and the
//! nearest-neighbour distance of Pitcher & Partridge 1979; see NOTES.md,
//! "Reference results from the literature").
//!
//! - polarization p = ‖Σ v̂ᵢ‖ / N: 1 when all swim the same way, near 0 when
//!   headings are random or the group mills.
//! - milling m = ‖Σ r̂ᵢ × v̂ᵢ‖ / N, r̂ᵢ the unit vector from the group centre to
//!   fish i: 1 for a perfect torus (fish circling the centre), near 0 otherwise.
//! - mean nearest-neighbour distance, in each fish's own body lengths (schooling
//!   fish keep about one body length).
//! - groups: clusters of fish linked by gaps of at most two body lengths.

use glam::Vec3;
use serde::Serialize;

use super::fish::Fish;
use super::spatial_grid::{Nearest, SpatialGrid};

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

/// Computes the metrics, reusing `grid` for neighbour queries (never all pairs).
/// A convenience for one-off measurements; [`SchoolMeter`] also keeps its other
/// buffers between calls.
pub fn measure(
    fish: &[Fish],
    tank_min_m: Vec3,
    tank_max_m: Vec3,
    grid: &mut SpatialGrid,
) -> SchoolMetrics {
    let mut meter = SchoolMeter {
        grid: std::mem::take(grid),
        ..SchoolMeter::default()
    };
    let metrics = meter.measure(fish, tank_min_m, tank_max_m);
    *grid = std::mem::take(&mut meter.grid);
    metrics
}

/// Measures [`SchoolMetrics`] every step without allocating: keeps its grid and
/// buffers. Cost O(N) plus the occupied cells' neighbourhoods (see
/// [`SchoolMeter::measure`]).
#[derive(Clone, Debug, Default)]
pub struct SchoolMeter {
    grid: SpatialGrid,
    positions_m: Vec<Vec3>,
    /// Union-find parent of each grid cell (groups are found cell by cell).
    cell_parent: Vec<u32>,
    /// Union-find parent of each fish (only when cells are too coarse, see below).
    fish_parent: Vec<u32>,
}

impl SchoolMeter {
    /// The metrics of `fish` in the tank `tank_min_m..tank_max_m`.
    ///
    /// Groups: the fish are bucketed into cubes whose diagonal is the shortest
    /// possible link (two of the smallest body lengths), so all fish in one cube
    /// belong to one group; cubes are then joined when any pair of their fish is
    /// linked. Union-find runs over cubes, not fish pairs, so a dense school of
    /// 20,000 costs a few cube comparisons per cube. Nearest neighbour: a
    /// ring-by-ring search from each fish ([`SpatialGrid::k_nearest`]).
    pub fn measure(&mut self, fish: &[Fish], tank_min_m: Vec3, tank_max_m: Vec3) -> SchoolMetrics {
        let n = fish.len();
        if n == 0 {
            return SchoolMetrics::default();
        }
        let count = n as f32;
        let mut heading_sum = Vec3::ZERO;
        let mut center = Vec3::ZERO;
        let mut speed_sum = 0.0_f32;
        let mut min_length = f32::INFINITY;
        let mut max_length = 0.0_f32;
        self.positions_m.clear();
        for f in fish {
            heading_sum += f.velocity_m_per_s.normalize_or_zero();
            center += f.position_m;
            speed_sum += f.speed_m_per_s();
            min_length = min_length.min(f.body_length_m);
            max_length = max_length.max(f.body_length_m);
            self.positions_m.push(f.position_m);
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
        let mean_speed_m_per_s = speed_sum / count;

        let min_length = min_length.max(1e-3);
        let max_length = max_length.max(min_length);
        let link_min_m = GROUP_LINK_BODY_LENGTHS * min_length;
        let link_max_m = GROUP_LINK_BODY_LENGTHS * max_length;
        // Cube diagonal just under the shortest link.
        let cell_m = link_min_m / 3f32.sqrt() * 0.999;
        self.grid
            .rebuild(tank_min_m, tank_max_m, cell_m, &self.positions_m);
        let actual_cell_m = self.grid.cell_m();
        let reach = (link_max_m / actual_cell_m).ceil() as i32;
        let groups = if actual_cell_m <= cell_m * 1.0001 {
            self.count_groups_by_cell(fish, reach)
        } else {
            // The grid had to use bigger cells (a huge tank or tiny fish): fall
            // back to linking fish pairs.
            self.count_groups_by_fish(fish, reach)
        };

        // Nearest neighbour, in the fish's own body lengths.
        let mut nnd_sum = 0.0_f32;
        if n > 1 {
            let far_m = (tank_max_m - tank_min_m).length() * 2.0 + 1.0;
            for (i, f) in fish.iter().enumerate() {
                let mut nearest = Nearest::new(1);
                self.grid.k_nearest(
                    f.position_m,
                    &self.positions_m,
                    far_m,
                    &mut nearest,
                    |j, _| j != i,
                );
                if let Some((_, d2)) = nearest.iter().next() {
                    nnd_sum += d2.sqrt() / f.body_length_m.max(1e-3);
                }
            }
        }
        let nnd_body_lengths = if n > 1 { nnd_sum / count } else { 0.0 };

        SchoolMetrics {
            polarization,
            milling,
            nnd_body_lengths,
            groups,
            mean_speed_m_per_s,
        }
    }

    fn count_groups_by_cell(&mut self, fish: &[Fish], reach: i32) -> u32 {
        let cells = self.grid.cell_count();
        self.cell_parent.clear();
        self.cell_parent.extend(0..cells as u32);
        let positions = &self.positions_m;
        let parent = &mut self.cell_parent;
        self.grid
            .for_each_cell_pair(reach, |a, b, points_a, points_b| {
                if a == b {
                    return;
                }
                let (ra, rb) = (root(parent, a), root(parent, b));
                if ra == rb {
                    return;
                }
                let linked = points_a.iter().any(|&i| {
                    points_b
                        .iter()
                        .any(|&j| linked(fish, positions, i as usize, j as usize))
                });
                if linked {
                    parent[ra.max(rb)] = ra.min(rb) as u32;
                }
            });
        let mut groups = 0;
        self.grid.for_each_cell_pair(0, |a, _, _, _| {
            if root(parent, a) == a {
                groups += 1;
            }
        });
        groups
    }

    fn count_groups_by_fish(&mut self, fish: &[Fish], reach: i32) -> u32 {
        self.fish_parent.clear();
        self.fish_parent.extend(0..fish.len() as u32);
        let positions = &self.positions_m;
        let parent = &mut self.fish_parent;
        self.grid
            .for_each_cell_pair(reach, |_, _, points_a, points_b| {
                for &i in points_a {
                    for &j in points_b {
                        let (i, j) = (i as usize, j as usize);
                        if i < j || (i > j && !std::ptr::eq(points_a, points_b)) {
                            let (ri, rj) = (root(parent, i), root(parent, j));
                            if ri != rj && linked(fish, positions, i, j) {
                                parent[ri.max(rj)] = ri.min(rj) as u32;
                            }
                        }
                    }
                }
            });
        (0..fish.len()).filter(|&i| root(parent, i) == i).count() as u32
    }
}

/// Are fish `i` and `j` within [`GROUP_LINK_BODY_LENGTHS`] of the larger one's
/// body length?
fn linked(fish: &[Fish], positions_m: &[Vec3], i: usize, j: usize) -> bool {
    let reach_m = GROUP_LINK_BODY_LENGTHS * fish[i].body_length_m.max(fish[j].body_length_m);
    positions_m[i].distance_squared(positions_m[j]) <= reach_m * reach_m
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
    use super::*;

    const LO: Vec3 = Vec3::new(-6.0, 0.0, -4.0);
    const HI: Vec3 = Vec3::new(6.0, 4.5, 4.0);

    fn fish_at(position: Vec3, velocity: Vec3) -> Fish {
        Fish::new(position, velocity, 0.4, 0.0)
    }

    fn metrics(fish: &[Fish]) -> SchoolMetrics {
        measure(fish, LO, HI, &mut SpatialGrid::default())
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
                let radial = Vec3::new(a.cos(), 0.0, a.sin());
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
        let mut parent: Vec<u32> = (0..n as u32).collect();
        let positions: Vec<Vec3> = fish.iter().map(|f| f.position_m).collect();
        let mut nnd = 0.0;
        for i in 0..n {
            let mut best = f32::INFINITY;
            for j in 0..n {
                if i != j {
                    best = best.min(positions[i].distance(positions[j]));
                    if linked(&fish, &positions, i, j) {
                        let (a, b) = (root(&mut parent, i), root(&mut parent, j));
                        parent[a.max(b)] = a.min(b) as u32;
                    }
                }
            }
            nnd += best / fish[i].body_length_m;
        }
        let groups = (0..n).filter(|&i| root(&mut parent, i) == i).count() as u32;
        let m = metrics(&fish);
        assert_eq!(m.groups, groups);
        assert!((m.nnd_body_lengths - nnd / n as f32).abs() < 1e-4);
    }
}
