//! Sharks and stingrays: a fish that sees a shark flees, and stingrays glide
//! near the sand, close ones avoided as one polygon.

use glam::Vec3;

use super::{assert_all_fish_legal, boid_world, world};
use crate::sim::boids::params::StingrayParams;
use crate::sim::boids::world::BoidParams;
use crate::sim::boids::{shark, stingray};
use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::Obstacle;

#[test]
fn a_fish_that_sees_a_shark_flees() {
    let mut w = boid_world(BoidParams::group(), 1);
    w.set_species_counts(1, 0);
    // The fish swims towards a (satiated, cruising) shark 3 m ahead.
    w.fish_mut()[0] = Fish::new(Vec3::new(1.0, 2.0, 0.0), Vec3::NEG_X * 0.5, 0.4, 0.0);
    w.sharks_mut()[0] = shark::new_shark(
        Vec3::new(-2.0, 2.0, 0.0),
        0.0,
        1.8,
        &w.world_params().shark_species,
    );
    w.sharks_mut()[0].satiated_secs = 10.0;
    let start_m = w.fish()[0]
        .position_m
        .distance(w.sharks()[0].body.position_m);
    for _ in 0..180 {
        w.step();
    }
    let end_m = w.fish()[0]
        .position_m
        .distance(w.sharks()[0].body.position_m);
    assert!(end_m > start_m + 0.5, "distance {start_m} → {end_m}");
    assert!(w.fish()[0].velocity_m_per_s.x > 0.0, "it turned away");
}

#[test]
fn stingrays_glide_near_the_sand_and_close_ones_are_avoided_as_one_polygon() {
    let mut w = world(3, 50);
    w.set_species_counts(0, 3);
    let floor_y_m = w.tank().min_m.y;
    // Three rays side by side in open water, in a clear spot.
    w.set_obstacles(Vec::new());
    for (k, ray) in w.stingrays_mut().iter_mut().enumerate() {
        *ray = stingray::new_stingray(
            Vec3::new(-1.5 + 1.5 * k as f32, 0.4, 0.0),
            0.0,
            floor_y_m,
            &StingrayParams::default(),
        );
    }
    w.step();
    assert_eq!(w.stingray_obstacles().len(), 1);
    assert!(matches!(
        w.stingray_obstacles()[0],
        Obstacle::Polygon { .. }
    ));
    for _ in 0..1200 {
        w.step();
        assert_all_fish_legal(&w);
    }
}
