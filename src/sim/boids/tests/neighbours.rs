//! The neighbour stage: the fish each fish heeds are the seven nearest it
//! sees (the "show vision" links), searched every few steps and rechecked in
//! between.

use super::boid_world;
use crate::sim::boids::forces::{self, Perception};
use crate::sim::boids::world::{BoidParams, NEIGHBOUR_SEARCH_EVERY_STEPS};
use crate::sim::common::fish::Fish;

/// The seven fish nearest to fish `i` of `school` that it sees, nearest
/// first, by brute force.
fn seven_nearest_seen(school: &[Fish], i: usize, perception: &Perception) -> Vec<usize> {
    let me = school[i];
    let mut seen: Vec<(f32, usize)> = (0..school.len())
        .filter(|&j| {
            j != i
                && forces::sees(
                    me.position_m,
                    me.heading(),
                    school[j].position_m,
                    perception,
                )
        })
        .map(|j| (school[j].position_m.distance_squared(me.position_m), j))
        .collect();
    seen.sort_by(|a, b| a.0.total_cmp(&b.0));
    seen.iter().take(7).map(|&(_, j)| j).collect()
}

#[test]
fn show_vision_links_are_the_seven_nearest_neighbours_the_fish_sees() {
    let mut w = boid_world(BoidParams::group(), 300);
    let mut links = Vec::new();
    w.interaction_neighbours(0, &mut links);
    assert!(links.is_empty(), "no step yet");
    let before: Vec<Fish> = w.fish().to_vec();
    w.step();
    let perception = BoidParams::group().perception;
    for i in [0, 17, 299] {
        w.interaction_neighbours(i, &mut links);
        // Brute force over the school as it was when the fish chose.
        assert_eq!(
            links,
            seven_nearest_seen(&before, i, &perception),
            "fish {i}"
        );
    }
    w.interaction_neighbours(300, &mut links);
    assert!(links.is_empty(), "no such fish");
    w.set_fish_count(100);
    w.interaction_neighbours(0, &mut links);
    assert!(links.is_empty(), "stale after a change of fish count");
}

#[test]
fn heeded_neighbours_are_always_seen_and_searched_every_few_steps() {
    let mut w = boid_world(BoidParams::group(), 400);
    for _ in 0..60 {
        w.step();
    }
    let perception = BoidParams::group().perception;
    let mut links = Vec::new();
    for _ in 0..NEIGHBOUR_SEARCH_EVERY_STEPS {
        let before: Vec<Fish> = w.fish().to_vec();
        let step = w.steps();
        w.step();
        let mut searched = 0;
        for (i, me) in before.iter().enumerate() {
            w.interaction_neighbours(i, &mut links);
            for &j in &links {
                assert!(
                    forces::sees(
                        me.position_m,
                        me.heading(),
                        before[j].position_m,
                        &perception
                    ),
                    "fish {i} heeds {j}, which it does not see"
                );
            }
            if (i as u64 + step).is_multiple_of(NEIGHBOUR_SEARCH_EVERY_STEPS) {
                searched += 1;
                assert_eq!(
                    links,
                    seven_nearest_seen(&before, i, &perception),
                    "fish {i} searched at step {step}"
                );
            } else {
                assert!(links.len() <= 7);
            }
        }
        assert_eq!(searched, 100, "a quarter of the fish search each step");
    }
}
