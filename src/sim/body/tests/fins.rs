//! The pectoral fins: pitched together they make the fish ascend or descend,
//! across the flow they brake it, and set unequally they yaw and roll it.

use glam::Vec3;
use std::f32::consts::{FRAC_PI_2, PI};

use super::swim;
use crate::sim::body::motor_bridge::{MotorIntent, level_turn_deg};
use crate::sim::body::physical_fish::{BodySpecies, PhysicalFish};
use crate::sim::body::swim_trials::LENGTH_M;
use crate::sim::body::{BodyCommand, FishBody, PectoralFins, SwimParams};
use crate::sim::common::fmath;

#[test]
fn pectoral_fin_pitch_makes_the_fish_ascend_or_descend() {
    let (level, h0) = swim(SwimParams::MAX, PectoralFins::NEUTRAL, 60.0);
    let (up, h1) = swim(SwimParams::MAX, PectoralFins::pitch(0.5), 60.0);
    let (down, h2) = swim(SwimParams::MAX, PectoralFins::pitch(-0.5), 60.0);
    let climb = |f: &FishBody, h: Vec3| (f.centre_of_mass_m() - h).z;
    let (dz0, dz1, dz2) = (climb(&level, h0), climb(&up, h1), climb(&down, h2));
    assert!(dz1 > dz0 + 0.005 * LENGTH_M, "no ascent: {dz1} vs {dz0}");
    assert!(dz2 < dz0 - 0.005 * LENGTH_M, "no descent: {dz2} vs {dz0}");
}

#[test]
fn braking_fins_reduce_speed() {
    let mut free = FishBody::new(LENGTH_M, Vec3::ZERO, Vec3::X);
    let mut braked = free.clone();
    for fish in [&mut free, &mut braked] {
        fish.set_uniform_velocity_m_per_s(Vec3::X * 0.2 * LENGTH_M);
    }
    let brake = BodyCommand {
        fins: PectoralFins::BRAKE,
        ..Default::default()
    };
    for _ in 0..40 {
        free.step(&BodyCommand::default(), Vec3::ZERO);
        braked.step(&brake, Vec3::ZERO);
    }
    let (v_free, v_braked) = (free.velocity_m_per_s().x, braked.velocity_m_per_s().x);
    assert!(v_braked < 0.8 * v_free, "braked {v_braked} free {v_free}");
}

#[test]
fn unequal_fins_yaw_and_roll_the_fish() {
    // Returns the heading change (degrees, + left) and the mean signed roll
    // (degrees, + = dorsal side leaning to the fish's right) while the fins hold.
    let swim = |fins: PectoralFins| {
        let mut fish = PhysicalFish::new(BodySpecies::Fish, 0.5, Vec3::ZERO, Vec3::X, 0.3);
        let cruise = MotorIntent {
            speed_fraction: 1.0,
            start_turn_deg: None,
            steer: 0.0,
            fins: PectoralFins::NEUTRAL,
        };
        for _ in 0..40 {
            fish.step(&cruise, Vec3::ZERO);
        }
        let heading = fish.heading();
        let mut roll_sum = 0.0;
        for _ in 0..100 {
            fish.step(&MotorIntent { fins, ..cruise }, Vec3::ZERO);
            let right = fish.heading().cross(Vec3::Y).normalize_or_zero();
            roll_sum += fmath::asin(fish.up().dot(right)).to_degrees();
        }
        (level_turn_deg(heading, fish.heading()), roll_sum / 100.0)
    };
    let (straight, level) = swim(PectoralFins::NEUTRAL);
    // The left fin across the flow drags the left side back: the fish yaws left.
    let (left_drag, _) = swim(PectoralFins {
        left_angle_rad: PI,
        right_angle_rad: FRAC_PI_2,
        ..PectoralFins::NEUTRAL
    });
    let (right_drag, _) = swim(PectoralFins {
        left_angle_rad: FRAC_PI_2,
        right_angle_rad: PI,
        ..PectoralFins::NEUTRAL
    });
    assert!(
        left_drag > straight + 3.0,
        "left drag {left_drag}°, straight {straight}°"
    );
    assert!(
        right_drag < straight - 3.0,
        "right drag {right_drag}°, straight {straight}°"
    );
    // Left fin lifting, right fin diving: the left side rises, the fish rolls to
    // its right; the mirror image rolls it left. The righting couple (the swim
    // bladder keeping the fish upright) keeps the roll small.
    let (_, to_right) = swim(PectoralFins {
        left_angle_rad: FRAC_PI_2 + 0.5,
        right_angle_rad: FRAC_PI_2 - 0.5,
        ..PectoralFins::NEUTRAL
    });
    let (_, to_left) = swim(PectoralFins {
        left_angle_rad: FRAC_PI_2 - 0.5,
        right_angle_rad: FRAC_PI_2 + 0.5,
        ..PectoralFins::NEUTRAL
    });
    assert!(
        to_right > level + 0.1 && to_left < level - 0.1,
        "roll: right {to_right}°, left {to_left}°, level {level}°"
    );
}
