//! The urges' weights, a cause test per slider: each weight moves the
//! school's measurements the way the papers say (dose-response), and the
//! weights alone make a school of the group preset and loners of the
//! individual one.

use super::{group_with, measure_minute};
use crate::sim::boids::world::BoidParams;

#[test]
fn the_weights_alone_make_a_school_of_the_group_and_loners_of_the_individuals() {
    let (group, individual) = (BoidParams::group(), BoidParams::individual());
    assert_eq!(
        BoidParams {
            weights: group.weights,
            ..individual
        },
        group,
        "the presets differ only in their weights"
    );
    let seeds = [1, 2, 3];
    let g = measure_minute(group, &seeds);
    let i = measure_minute(individual, &seeds);
    assert!(g.polarization > 0.8, "group {g:?}");
    assert!(g.groups <= 2.0, "group {g:?}");
    assert!((0.7..=1.5).contains(&g.nnd_body_lengths), "group {g:?}");
    assert!(i.polarization < 0.4, "individual {i:?}");
    assert!(
        i.nnd_body_lengths >= 1.5 * g.nnd_body_lengths,
        "individual {i:?} vs group {g:?}"
    );
    // Fish stay off the glass, sand and surface by steering, in both presets.
    assert!(g.at_edge < 0.005 && i.at_edge < 0.005, "{g:?} {i:?}");
}

#[test]
fn more_alignment_gives_higher_polarization() {
    let (lo, hi) = (
        measure_minute(group_with(1, 0.0), &[1, 2]),
        measure_minute(group_with(1, 50.0), &[1, 2]),
    );
    assert!(hi.polarization > lo.polarization + 0.3, "{lo:?} {hi:?}");
}

#[test]
fn more_cohesion_gives_a_smaller_nearest_neighbour_distance_and_fewer_groups() {
    let (lo, hi) = (
        measure_minute(group_with(2, 0.0), &[1, 2]),
        measure_minute(group_with(2, 60.0), &[1, 2]),
    );
    assert!(hi.nnd_body_lengths < lo.nnd_body_lengths, "{lo:?} {hi:?}");
    assert!(hi.groups < lo.groups, "{lo:?} {hi:?}");
}

#[test]
fn more_separation_gives_a_larger_nearest_neighbour_distance() {
    let (lo, hi) = (
        measure_minute(group_with(3, 10.0), &[1, 2]),
        measure_minute(group_with(3, 80.0), &[1, 2]),
    );
    assert!(
        hi.nnd_body_lengths > lo.nnd_body_lengths + 0.1,
        "{lo:?} {hi:?}"
    );
}

#[test]
fn more_containment_keeps_fish_further_from_the_edges_of_the_pond() {
    // Loners roam the whole pond, so the effect shows best with their weights.
    let with_containment = |level: f32| {
        let mut params = BoidParams::individual();
        params.weights[0] = level;
        params
    };
    let (lo, hi) = (
        measure_minute(with_containment(0.0), &[1, 2]),
        measure_minute(with_containment(100.0), &[1, 2]),
    );
    assert!(hi.in_edge_zone < 0.8 * lo.in_edge_zone, "{lo:?} {hi:?}");
}

#[test]
fn more_avoidance_keeps_fish_off_the_rocks_and_the_glass() {
    let (lo, hi) = (
        measure_minute(group_with(4, 0.0), &[1, 2]),
        measure_minute(group_with(4, 98.0), &[1, 2]),
    );
    assert!(hi.at_rock < lo.at_rock, "{lo:?} {hi:?}");
    // Without containment only avoidance keeps them off the glass.
    let mut bare = group_with(0, 0.0);
    bare.weights[4] = 0.0;
    let (lo, hi) = (
        measure_minute(bare, &[1]),
        measure_minute(group_with(0, 0.0), &[1]),
    );
    assert!(hi.at_edge < lo.at_edge, "{lo:?} {hi:?}");
}
