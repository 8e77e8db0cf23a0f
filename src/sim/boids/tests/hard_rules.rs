//! The hard rules: whatever the steering, the settings or the crowd, every
//! fish stays finite, in the tank and out of every rock, pillar, ledge and
//! stingray.

use super::{assert_all_fish_legal, boid_world, seed_with_a_ledge, world};
use crate::sim::boids::control_mode::ControlMode;
use crate::sim::boids::hard_rules::{OBSTACLE_MARGIN_M, TANK_MARGIN_M};
use crate::sim::boids::world::{BoidParams, World, WorldConfig};
use crate::sim::common::steering::SteeringParams;

#[test]
fn two_hundred_fish_stay_finite_in_the_tank_and_out_of_rocks_for_twenty_minutes() {
    // 20 simulated minutes in release; 5 in debug builds to keep
    // `cargo test` quick (the rules are checked at every step either way).
    let minutes = if cfg!(debug_assertions) { 5 } else { 20 };
    let mut w = world(1, 200);
    assert_all_fish_legal(&w);
    for _ in 0..minutes * 60 * 60 {
        w.step();
        assert_all_fish_legal(&w);
    }
    assert_eq!(w.non_finite_repairs(), 0);
    assert!((w.time_secs() - 60.0 * minutes as f64).abs() < 1e-3);
}

#[test]
fn steering_alone_keeps_fish_clear_of_glass_and_rocks() {
    // The hard rules are a safety net: in a normal run the soft steering
    // keeps every fish well away from glass and rock on its own.
    let mut w = world(2, 200);
    for _ in 0..3_600 {
        w.step();
        for fish in w.fish() {
            let p = fish.position_m;
            assert!(
                w.tank().contains(p, 2.0 * TANK_MARGIN_M),
                "at the glass: {p}"
            );
            for obstacle in w.obstacles() {
                assert!(
                    obstacle.signed_distance_m(p) > 2.0 * OBSTACLE_MARGIN_M,
                    "at a rock: {p}"
                );
            }
        }
    }
}

#[test]
fn five_thousand_fish_step_without_nan() {
    let mut w = world(11, 5_000);
    for _ in 0..60 {
        w.step();
    }
    assert_all_fish_legal(&w);
    assert_eq!(w.non_finite_repairs(), 0);
}

#[test]
fn absurd_or_nan_parameters_cannot_break_the_hard_rules() {
    let mut w = world(13, 50);
    // Far too fast, unlimited force, nonsense weights.
    *w.params_mut() = SteeringParams {
        max_speed_m_per_s: 50.0,
        min_speed_m_per_s: 40.0,
        max_force_m_per_s2: f32::INFINITY,
        containment_weight: -5.0,
        avoidance_weight: 0.0,
        ..SteeringParams::default()
    };
    for _ in 0..300 {
        w.step();
        assert_all_fish_legal(&w);
    }
    // NaN everywhere: the NaN guard replaces the force and says so.
    *w.params_mut() = SteeringParams {
        wander_weight: f32::NAN,
        wander_jitter_rad: f32::NAN,
        max_speed_m_per_s: f32::NAN,
        max_force_m_per_s2: f32::NAN,
        ..SteeringParams::default()
    };
    for _ in 0..300 {
        w.step();
        assert_all_fish_legal(&w);
    }
    assert!(w.non_finite_repairs() > 0);
    assert!(w.fish().iter().all(|f| f.wander_angle_rad.is_finite()));
}

#[test]
fn boids_with_every_slider_at_zero_or_maximum_stay_in_the_tank_and_finite() {
    for mode in ControlMode::ALL {
        for weights in [[0.0; 5], [100.0; 5]] {
            let params = BoidParams {
                mode,
                weights,
                ..BoidParams::group()
            };
            let mut w = boid_world(params, 300);
            w.set_species_counts(2, 4);
            for _ in 0..600 {
                w.step();
            }
            assert_all_fish_legal(&w);
            assert_eq!(w.non_finite_repairs(), 0, "{mode:?} {weights:?}");
        }
    }
}

#[test]
fn five_thousand_schooling_fish_with_sharks_and_stingrays_stay_legal() {
    let mut w = World::new(WorldConfig {
        seed: 11,
        fish_count: 5_000,
        sharks: 3,
        stingrays: 6,
        obstacles: None,
    });
    w.set_boids(Some(BoidParams::group()));
    for _ in 0..60 {
        w.step();
    }
    assert_all_fish_legal(&w);
    assert_eq!(w.non_finite_repairs(), 0);
    assert_eq!(w.fish().len(), 5_000);
}

#[test]
fn no_fish_ever_enters_a_rock_pillar_ledge_or_stingray_in_a_long_run() {
    let mut w = World::new(WorldConfig {
        seed: seed_with_a_ledge(),
        fish_count: 200,
        sharks: 1,
        stingrays: 8,
        obstacles: None,
    });
    w.set_boids(Some(BoidParams::group()));
    for _ in 0..2 * 60 * 60 {
        w.step();
        assert_all_fish_legal(&w);
    }
    assert_eq!(w.non_finite_repairs(), 0);
}
