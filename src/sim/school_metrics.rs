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
use super::spatial_grid::SpatialGrid;

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
pub fn measure(
    fish: &[Fish],
    tank_min_m: Vec3,
    tank_max_m: Vec3,
    grid: &mut SpatialGrid,
) -> SchoolMetrics {
    let n = fish.len();
    if n == 0 {
        return SchoolMetrics::default();
    }
    let count = n as f32;
    let headings: Vec<Vec3> = fish
        .iter()
        .map(|f| f.velocity_m_per_s.normalize_or_zero())
        .collect();
    let center = fish.iter().map(|f| f.position_m).sum::<Vec3>() / count;
    let polarization = (headings.iter().sum::<Vec3>().length() / count).min(1.0);
    let milling = (fish
        .iter()
        .zip(&headings)
        .map(|(f, &h)| (f.position_m - center).normalize_or_zero().cross(h))
        .sum::<Vec3>()
        .length()
        / count)
        .min(1.0);
    let mean_speed_m_per_s = fish.iter().map(Fish::speed_m_per_s).sum::<f32>() / count;

    let max_length = fish
        .iter()
        .map(|f| f.body_length_m)
        .fold(0.0_f32, f32::max)
        .max(1e-3);
    let link_m = GROUP_LINK_BODY_LENGTHS * max_length;
    let positions: Vec<Vec3> = fish.iter().map(|f| f.position_m).collect();
    grid.rebuild(tank_min_m, tank_max_m, link_m, &positions);

    // Groups: union-find over links of ≤ 2 body lengths.
    let mut parent: Vec<usize> = (0..n).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    for i in 0..n {
        grid.for_each_candidate(positions[i], link_m, |j| {
            if j > i {
                let reach =
                    GROUP_LINK_BODY_LENGTHS * fish[i].body_length_m.max(fish[j].body_length_m);
                if positions[i].distance(positions[j]) <= reach {
                    let (a, b) = (root(&mut parent, i), root(&mut parent, j));
                    parent[a.max(b)] = a.min(b);
                }
            }
        });
    }
    let groups = (0..n).filter(|&i| root(&mut parent, i) == i).count() as u32;

    // Nearest neighbour: widen the search until one is found.
    let mut nnd_sum = 0.0_f32;
    if n > 1 {
        for i in 0..n {
            let mut radius = link_m;
            let nearest = loop {
                let mut best = f32::INFINITY;
                grid.for_each_candidate(positions[i], radius, |j| {
                    if j != i {
                        best = best.min(positions[i].distance(positions[j]));
                    }
                });
                // A candidate beyond `radius` may hide a nearer one in an unvisited cell.
                if best <= radius || radius > (tank_max_m - tank_min_m).length() * 2.0 {
                    break best;
                }
                radius *= 2.0;
            };
            if nearest.is_finite() {
                nnd_sum += nearest / fish[i].body_length_m.max(1e-3);
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
}
