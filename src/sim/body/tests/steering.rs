//! The bridge from the steering layer: a physical fish told where to swim turns
//! there in time, with a bounded radius, symmetrically, and reaches a point
//! beside it.

use glam::Vec3;

use crate::sim::body::physical_fish::trials::{closed_loop_turn, open_loop_steer};
use crate::sim::body::physical_fish::{BodySpecies, PhysicalFish};

#[test]
fn the_bridge_steers_a_physical_fish_to_a_target_beside_it() {
    let mut fish = PhysicalFish::new(BodySpecies::Fish, 0.5, Vec3::ZERO, Vec3::X, 0.3);
    // 4 m away, 90° to the fish's left (left of +x is −z with y up).
    let target = Vec3::new(0.0, 0.0, -4.0);
    let dt = fish.body().dt_secs();
    let mut reached = None;
    for step in 0..(90.0 / dt) as usize {
        let to_target = target - fish.point.position_m;
        if to_target.length() < fish.body_length_m() {
            reached = Some(step as f32 * dt);
            break;
        }
        let desired = to_target.normalize_or_zero() * fish.top_speed_m_per_s();
        let intent = fish.plan(desired);
        fish.step(&intent, Vec3::ZERO);
    }
    let secs = reached.expect("the fish reaches the target within 90 s");
    assert!(secs > 10.0, "it swims there, no teleport: {secs} s");
}

#[test]
fn a_fish_told_to_swim_90_degrees_aside_turns_80_degrees_within_3_5_s() {
    let (secs, _, radius_bl) = closed_loop_turn(90.0, 0.7);
    assert!(secs <= 3.5, "{secs} s");
    // The radius bound was 1.0 when this test was written (commit 173515b) on the
    // unconverged body (8 implicit-Euler substeps, spring damping 0.1), where this
    // turn measured 0.66 body lengths. On the converged body (12 BDF2 substeps,
    // spring damping 2.0, biases 0.5/0.5/0.25) it measures 1.085: the stiffer,
    // damped body bends less for the same held bend. Stronger biases turn tighter
    // (0.75/0.75/0.375: 0.73) but fold schooling fish below 0.85 of their length
    // (docs/fish-body.md, "Steering on the converged body"), so 1.2 is the bound
    // for this body's honest radius, with about 10 % margin.
    assert!(radius_bl < 1.2, "radius {radius_bl} body lengths");
}

#[test]
fn steering_left_and_right_is_symmetric() {
    let (left, _) = open_loop_steer(1.0, 1.0, [1.0, 1.0, 0.5]);
    let (right, _) = open_loop_steer(1.0, -1.0, [1.0, 1.0, 0.5]);
    assert!(left > 20.0, "{left}°/s");
    assert!(
        (left + right).abs() < 0.05 * left,
        "left {left}°/s, right {right}°/s"
    );
}

#[test]
fn a_fish_chasing_a_point_beside_it_reaches_it() {
    let mut fish = PhysicalFish::new(BodySpecies::Fish, 0.5, Vec3::ZERO, Vec3::X, 0.3);
    let dt = fish.body().dt_secs();
    // 1.5 m away, 90° to the left: a point-mass chaser's job.
    let target = Vec3::new(0.0, 0.0, -1.5);
    let mut reached = None;
    for step in 0..(30.0 / dt) as usize {
        let to_target = target - fish.point.position_m;
        if to_target.length() < 0.5 * fish.body_length_m() {
            reached = Some(step as f32 * dt);
            break;
        }
        let intent = fish.plan(to_target.normalize_or_zero() * 0.7 * fish.top_speed_m_per_s());
        fish.step(&intent, Vec3::ZERO);
    }
    let secs = reached.expect("within half a body length in 30 s");
    println!("reached in {secs} s");
    assert!(secs < 15.0, "{secs} s");
}
