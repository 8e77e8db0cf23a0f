//! The turn-MC: each key turn lands near its target, left and right mirror each
//! other, the steering map grows with the angle, turns beyond 90° are sequences,
//! and a physical fish turns by the key's angle at every swim speed.

use crate::sim::body::turn_mc::{
    SteeringMap, TurnDirection, TurnMc, measure_heading_change_deg, measure_turn_deg,
    mirror_muscles,
};

use crate::sim::body::physical_fish::trials::turn_at_speed_deg;

#[test]
fn each_key_turn_lands_within_10_degrees_of_its_target() {
    for (target, params) in SteeringMap::DEFAULT.keys {
        let left = measure_turn_deg(params, TurnDirection::Left);
        let right = measure_turn_deg(params, TurnDirection::Right);
        assert!((left - target).abs() <= 10.0, "left {target}°: {left}°");
        assert!((right + target).abs() <= 10.0, "right {target}°: {right}°");
    }
}

#[test]
fn left_and_right_turns_are_mirror_images() {
    // The controller: a right turn contracts exactly the mirror muscles.
    let (mut left, mut right) = (TurnMc::default(), TurnMc::default());
    left.start_turn(50.0);
    right.start_turn(-50.0);
    let mut steps = 0;
    while left.is_turning() || right.is_turning() {
        let (l, r) = (left.step(0.055), right.step(0.055));
        assert_eq!(mirror_muscles(&l), r);
        steps += 1;
        assert!(steps < 10_000);
    }
    assert!(steps > 10);
    // The body: mirror-image turns, up to rounding.
    let params = SteeringMap::DEFAULT.params_for_angle(50.0);
    let l = measure_turn_deg(params, TurnDirection::Left);
    let r = measure_turn_deg(params, TurnDirection::Right);
    assert!(l > 0.0 && (l + r).abs() < 0.5, "left {l}° right {r}°");
}

#[test]
fn steering_map_is_monotonic_in_angle() {
    let map = SteeringMap::DEFAULT;
    let mut previous = map.params_for_angle(0.0);
    assert_eq!(previous.anterior_amplitude, 0.0);
    for deg in 1..=90 {
        let p = map.params_for_angle(deg as f32);
        assert!(p.anterior_amplitude > previous.anterior_amplitude, "{deg}°");
        assert!(
            p.posterior_amplitude > previous.posterior_amplitude,
            "{deg}°"
        );
        previous = p;
    }
    // Beyond 90° a single turn saturates; the sign only picks the side.
    assert_eq!(map.params_for_angle(120.0), map.params_for_angle(90.0));
    assert_eq!(map.params_for_angle(-40.0), map.params_for_angle(40.0));
    // The measured turn grows with the requested angle and follows it.
    let mut last = f32::NEG_INFINITY;
    for deg in [10.0, 20.0, 35.0, 50.0, 75.0, 90.0] {
        let got = measure_turn_deg(map.params_for_angle(deg), TurnDirection::Left);
        assert!(got > last, "{deg}°: {got}° after {last}°");
        assert!((got - deg).abs() <= 10.0, "{deg}° requested, {got}° turned");
        last = got;
    }
}

#[test]
fn turns_beyond_90_degrees_are_sequences_of_smaller_turns() {
    let mut mc = TurnMc::default();
    mc.start_turn(180.0);
    // Two 90° turns back to back: the anterior muscle rises twice.
    let mut rises = 0;
    let mut previous = 0.0;
    let mut rising = false;
    while mc.is_turning() {
        let u = mc.step(0.055)[0];
        if u > previous && !rising {
            rises += 1;
        }
        rising = u > previous;
        previous = u;
    }
    assert_eq!(rises, 2);
    let mut mc = TurnMc::default();
    mc.start_turn(-180.0);
    let turned = measure_heading_change_deg(&mut mc, true);
    assert!((turned + 180.0).abs() <= 20.0, "turned {turned}°");
}

#[test]
fn key_turns_hold_at_every_swim_speed() {
    // The turn-MC's keys are measured at full thrust; a fish asked to swim
    // slower still turns by the key's angle (it used to turn 90° × its
    // speed, roughly).
    for key in [30.0, 90.0, -60.0] {
        for speed in [0.3, 0.6, 1.0] {
            let turned = turn_at_speed_deg(key, speed);
            assert!(
                (turned - key).abs() < 0.1 * key.abs().max(30.0),
                "key {key}° at speed {speed}: turned {turned}°"
            );
        }
    }
}
