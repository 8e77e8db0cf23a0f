//! The attention inspector: what a fish heeded and how its urges made its
//! steering, replayed from the step's record; asking changes nothing, and a
//! change of the school withdraws the report.

use glam::Vec3;

use crate::sim::boids::control_mode::ControlMode;
use crate::sim::boids::forces;
use crate::sim::boids::urges::boid_steering_params;
use crate::sim::boids::world::{BoidParams, DT_SECS, World, WorldConfig};
use crate::sim::common::spatial_grid::SpatialGrid;
use crate::sim::common::steering;

/// A schooling tank (Table 1's group weights in `mode`), stepped `steps` times.
fn school(mode: ControlMode, sharks: usize, steps: usize) -> World {
    let mut w = World::new(WorldConfig {
        seed: 5,
        fish_count: 120,
        sharks,
        ..WorldConfig::default()
    });
    w.set_boids(Some(BoidParams {
        mode,
        ..BoidParams::group()
    }));
    for _ in 0..steps {
        w.step();
    }
    w
}

#[test]
fn the_heeded_neighbours_are_the_steps_search() {
    let mut w = school(ControlMode::Blended, 0, 0);
    assert_eq!(w.attention(0), None, "no step yet: nothing to report");
    let before = w.clone();
    // The first boid step searches every fish's neighbours from scratch.
    w.step();
    let positions: Vec<Vec3> = before.fish().iter().map(|f| f.position_m).collect();
    let velocities: Vec<Vec3> = before.fish().iter().map(|f| f.velocity_m_per_s).collect();
    let mut grid = SpatialGrid::default();
    let tank = before.tank();
    grid.rebuild(tank.min_m, tank.max_m, 0.5, &positions);
    let boids = *w.boids().unwrap();
    let tuning = w.world_params().steering;
    let mut links = Vec::new();
    let mut heeding = 0;
    for i in 0..w.fish().len() {
        let attention = w.attention(i).unwrap();
        let mut searched: Vec<usize> = forces::heeded_neighbours(
            &positions,
            &velocities,
            i,
            &grid,
            &boids.perception,
            &tuning,
        )
        .iter()
        .map(|(j, _)| j)
        .collect();
        let mut heeded = attention.neighbours.clone();
        w.interaction_neighbours(i, &mut links);
        assert_eq!(heeded, links, "fish {i}: the vision links' list");
        assert!(heeded.len() <= tuning.topological_neighbours);
        searched.sort_unstable();
        heeded.sort_unstable();
        assert_eq!(heeded, searched, "fish {i}");
        heeding += usize::from(!heeded.is_empty());
    }
    assert!(heeding > 100, "most fish heed someone: {heeding}");
    // Later steps recheck the lists in between searches; still the step's own.
    for _ in 0..7 {
        w.step();
    }
    for i in 0..w.fish().len() {
        w.interaction_neighbours(i, &mut links);
        assert_eq!(w.attention(i).unwrap().neighbours, links);
    }
}

/// Replays the last step's integration of every fish from the reported
/// steering and compares with where the step left it: the reported urges,
/// combined by the mode's rule, are the steering the fish felt.
fn assert_urges_explain_the_velocity_change(mode: ControlMode, sharks: usize) {
    let mut w = school(mode, sharks, 30);
    let before = w.clone();
    w.step();
    let boids = *w.boids().unwrap();
    let params = boid_steering_params(w.params(), &boids.perception);
    let mut checked = 0;
    for i in 0..w.fish().len() {
        let a = w.attention(i).unwrap();
        assert_eq!(a.velocity_before_m_per_s, before.fish()[i].velocity_m_per_s);
        // The mode's rule: the applied urges' sum, limited.
        let sum: Vec3 = (0..5)
            .filter(|&k| a.applied[k])
            .map(|k| a.urges_m_per_s2[k])
            .sum();
        let combined = steering::limit(sum, boids.perception.max_force_m_per_s2);
        assert_eq!(a.combined_m_per_s2, combined);
        assert_eq!(
            a.steering_m_per_s2,
            combined + a.wander_m_per_s2 + a.escape_m_per_s2
        );
        let mut replay = before.fish()[i];
        replay.integrate(a.steering_m_per_s2, &params, DT_SECS);
        let after = w.fish()[i];
        // Skip fish the hard rules touched (at the glass or a rock).
        if replay.position_m.distance(after.position_m) > 1e-6 {
            continue;
        }
        assert!(
            replay.velocity_m_per_s.distance(a.velocity_m_per_s) < 1e-6,
            "{mode:?} fish {i}: replayed {} against {}",
            replay.velocity_m_per_s,
            a.velocity_m_per_s
        );
        checked += 1;
    }
    assert!(checked > 100, "{mode:?}: only {checked} fish checked");
}

#[test]
fn the_reported_urges_are_the_steering_of_the_step_in_every_mode() {
    for mode in ControlMode::ALL {
        assert_urges_explain_the_velocity_change(mode, 0);
    }
    assert_urges_explain_the_velocity_change(ControlMode::Blended, 2);
}

#[test]
fn each_mode_marks_the_urges_its_rule_applies() {
    for mode in ControlMode::ALL {
        let w = school(mode, 0, 20);
        let mut counts = [0usize; 6];
        for i in 0..w.fish().len() {
            let a = w.attention(i).unwrap();
            let applied = a.applied.iter().filter(|&&x| x).count();
            counts[applied] += 1;
            match mode {
                // Every urge with a weight, every step.
                ControlMode::Blended => assert_eq!(a.applied, [true; 5]),
                // The most pressing urge alone (none when nothing pulls).
                ControlMode::Classic => {
                    assert!(applied <= 1);
                    let pulls = a.urges_m_per_s2.iter().any(|u| *u != Vec3::ZERO);
                    assert_eq!(applied == 1, pulls, "fish {i}");
                }
                // One ticket drawn.
                ControlMode::MonteCarlo => assert_eq!(applied, 1),
                // Each urge whose weight beat the one dice roll: a lighter
                // urge is applied only with every heavier one.
                ControlMode::DirectAlternate => {
                    for k in 0..5 {
                        for m in 0..5 {
                            if a.applied[k] && a.weights[m] > a.weights[k] {
                                assert!(a.applied[m], "fish {i}: {k} without {m}");
                            }
                        }
                    }
                }
            }
        }
        assert!(counts.iter().sum::<usize>() == w.fish().len(), "{counts:?}");
    }
}

#[test]
fn asking_changes_nothing_and_a_change_of_the_school_withdraws_the_report() {
    let mut asked = school(ControlMode::MonteCarlo, 1, 10);
    let mut plain = asked.clone();
    for _ in 0..20 {
        for i in 0..asked.fish().len() {
            assert!(asked.attention(i).is_some());
        }
        asked.step();
        plain.step();
    }
    for (a, b) in asked.fish().iter().zip(plain.fish()) {
        assert_eq!(a.position_m, b.position_m);
        assert_eq!(a.velocity_m_per_s, b.velocity_m_per_s);
    }
    assert!(asked.attention(119).is_some());
    assert_eq!(asked.attention(120), None, "no such fish");
    asked.set_fish_count(50);
    assert_eq!(asked.attention(10), None, "until the next step");
    asked.step();
    assert!(asked.attention(10).is_some());
    assert_eq!(asked.attention(60), None);
    asked.set_obstacles(Vec::new());
    assert_eq!(asked.attention(10), None, "the rocks changed");
    asked.set_boids(None);
    asked.step();
    assert_eq!(asked.attention(10), None, "wandering fish have no urges");
}

/// No hidden hand: a fleeing fish's changed weights are in its report, and the
/// attention panel's sentence says them (cohesion up, separation down, by the
/// world's fear factors), while a calm fish's weights are the sliders'.
#[test]
fn a_frightened_fishs_changed_weights_are_shown() {
    let w = school(ControlMode::Blended, 2, 240);
    let fear = w.world_params().clone();
    let group = BoidParams::group().weights;
    let (mut calm, mut frightened) = (0, 0);
    for i in 0..w.fish().len() {
        let a = w.attention(i).unwrap();
        if a.fleeing {
            frightened += 1;
            assert!(
                (a.weights[2] - (group[2] * fear.fear_cohesion_factor).min(100.0)).abs() < 1e-4
            );
            assert!((a.weights[3] - group[3] * fear.fear_separation_factor).abs() < 1e-4);
            let sentence = crate::i18n::with_lang(crate::i18n::Lang::En, || {
                crate::ui::boids_attention::fear_sentence(&a, false)
            });
            assert!(
                sentence.contains("cohesion 58") && sentence.contains("separation 13"),
                "{sentence}"
            );
        } else {
            calm += 1;
            assert_eq!(a.weights, group);
        }
    }
    assert!(
        frightened > 0 && calm > 0,
        "{frightened} frightened, {calm} calm"
    );
}
