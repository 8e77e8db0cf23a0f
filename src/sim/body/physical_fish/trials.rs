//! Measured manoeuvres of a physical fish (0.5 m long, driven through the
//! bridge or through its swim-MC and turn-MC directly): a turn at a swim speed,
//! the straight speed at an amplitude, closed- and open-loop steering, a held
//! bend and an about-turn. The body's tests assert on them and its census
//! scripts print them (`sim/body/census.rs`), so both measure the same way. A
//! child of `physical_fish` because several step the fish's body and
//! controllers directly. Native only.

use super::*;
use crate::sim::body::SwimParams;
use crate::sim::body::motor_bridge::level_turn_deg;

/// A fish swims straight at `speed_fraction` for 3 s, is told to turn
/// `angle_deg` (a hand command, or a routine's turn-MC choice), keeps being
/// asked for `speed_fraction` until the turn is done and 2 s more. Returns
/// the change of its fore body's level heading, each end averaged over 1 s
/// (the turn-MC's own protocol, `body::turn_mc`), degrees, + = left.
pub fn turn_at_speed_deg(angle_deg: f32, speed_fraction: f32) -> f32 {
    turn_at_speed_after_deg(angle_deg, speed_fraction, 0)
}

/// [`turn_at_speed_deg`] with the turn requested `extra_steps` steps later
/// (at another phase of the tail beat).
pub fn turn_at_speed_after_deg(angle_deg: f32, speed_fraction: f32, extra_steps: usize) -> f32 {
    turn_with_map_deg(
        crate::sim::body::turn_mc::SteeringMap::DEFAULT,
        angle_deg,
        speed_fraction,
        extra_steps,
    )
}

/// [`turn_at_speed_after_deg`] by a fish whose turn-MC uses `map`.
pub fn turn_with_map_deg(
    map: crate::sim::body::turn_mc::SteeringMap,
    angle_deg: f32,
    speed_fraction: f32,
    extra_steps: usize,
) -> f32 {
    let mut fish = PhysicalFish::new(BodySpecies::Fish, 0.5, Vec3::ZERO, Vec3::X, 0.3);
    fish.turn.map = map;
    let dt = fish.body().dt_secs();
    let swim = MotorIntent {
        speed_fraction,
        start_turn_deg: None,
        steer: 0.0,
        fins: PectoralFins::NEUTRAL,
    };
    let window = (1.0 / dt).round() as usize;
    let mut headings: Vec<f32> = Vec::new();
    let mut unwrapped = 0.0f32;
    let mut run = |fish: &mut PhysicalFish, intent: &MotorIntent, headings: &mut Vec<f32>| {
        let before = level_turn_deg(Vec3::X, fish.forward());
        fish.step(intent, Vec3::ZERO);
        let after = level_turn_deg(Vec3::X, fish.forward());
        unwrapped += (after - before + 180.0).rem_euclid(360.0) - 180.0;
        headings.push(unwrapped);
    };
    for _ in 0..(3.0 / dt) as usize + extra_steps {
        run(&mut fish, &swim, &mut headings);
    }
    let mean = |h: &[f32]| h[h.len() - window..].iter().sum::<f32>() / window as f32;
    let start = mean(&headings);
    run(
        &mut fish,
        &MotorIntent {
            start_turn_deg: Some(angle_deg),
            ..swim
        },
        &mut headings,
    );
    for _ in 0..(60.0 / dt) as usize {
        if !fish.is_turning() {
            break;
        }
        run(&mut fish, &swim, &mut headings);
    }
    for _ in 0..(2.0 / dt) as usize {
        run(&mut fish, &swim, &mut headings);
    }
    mean(&headings) - start
}

/// A 0.5 m fish swimming straight at `amplitude` of r̂ (frequencies ŝ): its
/// mean speed over the last 20 s of a 40 s run, metres per second.
pub fn straight_speed_at_amplitude(amplitude: f32) -> f32 {
    let mut fish = PhysicalFish::new(BodySpecies::Fish, 0.5, Vec3::ZERO, Vec3::X, 0.3);
    let dt = fish.body().dt_secs();
    let mut swim = SwimMc::default();
    let params = SwimParams {
        anterior_amplitude: amplitude,
        posterior_amplitude: amplitude,
        ..SwimParams::MAX
    };
    let steps = (40.0 / dt) as usize;
    let mut half = Vec3::ZERO;
    for k in 0..steps {
        fish.body
            .step_with(&PectoralFins::NEUTRAL, Vec3::ZERO, |t| {
                swim.muscles_at(&params, t)
            });
        swim.advance(&params, dt);
        fish.sync_point();
        if k + 1 == steps / 2 {
            half = fish.point.position_m;
        }
    }
    (fish.point.position_m - half).length() / (dt * (steps - steps / 2) as f32)
}

/// A 0.5 m fish swims straight at `speed_fraction` for 3 s, then is told to
/// swim at the same speed in a fixed direction `angle_deg` to its left.
/// Returns (seconds until the heading has turned 90 % of the angle, peak
/// heading rate over 1 s in °/s, turning radius over that part in body
/// lengths: path length / heading change).
pub fn closed_loop_turn(angle_deg: f32, speed_fraction: f32) -> (f32, f32, f32) {
    let mut fish = PhysicalFish::new(BodySpecies::Fish, 0.5, Vec3::ZERO, Vec3::X, 0.3);
    let dt = fish.body().dt_secs();
    let speed = speed_fraction * fish.top_speed_m_per_s();
    for _ in 0..(3.0 / dt) as usize {
        let intent = fish.plan(Vec3::X * speed);
        fish.step(&intent, Vec3::ZERO);
    }
    let start = fish.heading();
    let goal = glam::Quat::from_rotation_y(angle_deg.to_radians()) * start;
    let mut turned = Vec::new();
    let mut path_m = 0.0;
    let mut last = fish.point.position_m;
    let mut done = None;
    let mut unwrapped = 0.0f32;
    let mut prev = 0.0f32;
    for step in 0..(30.0 / dt) as usize {
        let intent = fish.plan(goal * speed);
        fish.step(&intent, Vec3::ZERO);
        let h = level_turn_deg(start, fish.heading());
        unwrapped += (h - prev + 180.0).rem_euclid(360.0) - 180.0;
        prev = h;
        turned.push(unwrapped);
        if done.is_none() {
            path_m += fish.point.position_m.distance(last);
        }
        last = fish.point.position_m;
        if done.is_none() && unwrapped * angle_deg.signum() >= 0.9 * angle_deg.abs() {
            done = Some(step + 1);
        }
    }
    let done = done.unwrap_or(turned.len());
    let window = (1.0 / dt).round() as usize;
    let peak = (window..turned.len())
        .map(|i| (turned[i] - turned[i - window]).abs() / (window as f32 * dt))
        .fold(0.0, f32::max);
    let radius_bl = path_m / turned[done - 1].to_radians().abs().max(1e-3) / 0.5;
    (done as f32 * dt, peak, radius_bl)
}

/// Open loop: a default body swims at `speed_fraction` for 3 s, then holds
/// `steer` with `biases` for 4 s. Returns the mean heading rate over the last
/// 3 s (°/s) and the radius of the path (body lengths).
pub fn open_loop_steer(speed_fraction: f32, steer: f32, biases: [f32; 3]) -> (f32, f32) {
    use crate::sim::body::turn_mc::add_steering_with;
    let mut fish = PhysicalFish::new(BodySpecies::Fish, 0.5, Vec3::ZERO, Vec3::X, 0.3);
    let dt = fish.body().dt_secs();
    let mut swim = SwimMc::default();
    let mut run = |fish: &mut PhysicalFish, s: f32| {
        let params = swim.params_for_speed(speed_fraction);
        fish.body
            .step_with(&PectoralFins::NEUTRAL, Vec3::ZERO, |t| {
                let mut u = swim.muscles_at(&params, t);
                add_steering_with(&mut u, s, biases);
                u
            });
        swim.advance(&params, dt);
        fish.update_heading();
        fish.sync_point();
    };
    for _ in 0..(4.0 / dt) as usize {
        run(&mut fish, 0.0);
    }
    for _ in 0..(1.0 / dt) as usize {
        run(&mut fish, steer);
    }
    let h0 = fish.heading();
    let mut path = 0.0;
    let mut turned = 0.0;
    let mut prev = h0;
    for _ in 0..(3.0 / dt) as usize {
        let last = fish.point.position_m;
        run(&mut fish, steer);
        path += fish.point.position_m.distance(last);
        turned += level_turn_deg(prev, fish.heading());
        prev = fish.heading();
    }
    (
        turned / 3.0,
        path / turned.to_radians().abs().max(1e-3) / 0.5,
    )
}

/// A 0.5 m fish swims straight at `speed_fraction` for `lead_secs`, then is
/// told to swim at the same speed `angle_deg` to its left, steering through
/// the bridge with the segment `biases` (`body::turn_mc::add_steering_with`).
/// Returns the seconds until its heading has turned 90 % of the angle (`None`
/// if not within 15 s) and the shortest spine seen, as a fraction of the body
/// length.
pub fn closed_loop_turn_with(
    angle_deg: f32,
    speed_fraction: f32,
    lead_secs: f32,
    biases: [f32; 3],
) -> (Option<f32>, f32) {
    use crate::sim::body::turn_mc::{add_steering_with, combine_swim_and_turn};
    let mut fish = PhysicalFish::new(BodySpecies::Fish, 0.5, Vec3::ZERO, Vec3::X, 0.3);
    let dt = fish.body().dt_secs();
    let speed = speed_fraction * fish.top_speed_m_per_s();
    let go = |fish: &mut PhysicalFish, desired: Vec3| {
        let intent = fish.plan(desired);
        let params = fish.swim.params_for_speed(intent.speed_fraction);
        let (swim, turn) = (&fish.swim, &fish.turn);
        fish.body.step_with(&intent.fins, Vec3::ZERO, |t| {
            let mut m = combine_swim_and_turn(&swim.muscles_at(&params, t), &turn.muscles_at(t));
            add_steering_with(&mut m, intent.steer, biases);
            m
        });
        fish.swim.advance(&params, dt);
        fish.update_heading();
        fish.sync_point();
    };
    for _ in 0..(lead_secs / dt) as usize {
        go(&mut fish, Vec3::X * speed);
    }
    let start = fish.heading();
    let goal = glam::Quat::from_rotation_y(angle_deg.to_radians()) * start;
    let (mut unwrapped, mut prev, mut shortest) = (0.0f32, 0.0f32, 1.0f32);
    for step in 0..(15.0 / dt) as usize {
        go(&mut fish, goal * speed);
        let h = level_turn_deg(start, fish.heading());
        unwrapped += (h - prev + 180.0).rem_euclid(360.0) - 180.0;
        prev = h;
        shortest = shortest.min(fish.body().spine_length_m() / fish.body_length_m());
        if unwrapped * angle_deg.signum() >= 0.9 * angle_deg.abs() {
            return (Some((step + 1) as f32 * dt), shortest);
        }
    }
    (None, shortest)
}

/// The intent of a fish cruising straight at 0.7 of its top speed.
pub const CRUISE: MotorIntent = MotorIntent {
    speed_fraction: 0.7,
    start_turn_deg: None,
    steer: 0.0,
    fins: PectoralFins::NEUTRAL,
};

/// A 0.5 m fish after 4 s of [`CRUISE`] (`setup` runs first).
pub fn cruising_fish(setup: impl FnOnce(&mut PhysicalFish)) -> PhysicalFish {
    let mut fish = PhysicalFish::new(BodySpecies::Fish, 0.5, Vec3::ZERO, Vec3::X, 0.3);
    setup(&mut fish);
    let dt = fish.body().dt_secs();
    for _ in 0..(4.0 / dt) as usize {
        fish.step(&CRUISE, Vec3::ZERO);
    }
    fish
}

/// A 0.5 m fish after 4 s of [`CRUISE`] holds the full bend (steer 1) with the
/// swim-MC at `speed_fraction` and `fins` for 8 s. Returns its speed (m/s),
/// heading rate (°/s) and path radius (body lengths) over the last 6 s.
pub fn held_bend(speed_fraction: f32, fins: PectoralFins) -> (f32, f32, f32) {
    let mut fish = cruising_fish(|_| {});
    let dt = fish.body().dt_secs();
    let cruise = CRUISE;
    let bend = MotorIntent {
        speed_fraction,
        steer: 1.0,
        fins,
        ..cruise
    };
    for _ in 0..(2.0 / dt) as usize {
        fish.step(&bend, Vec3::ZERO);
    }
    let (mut path, mut turned, mut prev) = (0.0f32, 0.0f32, fish.heading());
    let steps = (6.0 / dt) as usize;
    for _ in 0..steps {
        let last = fish.point.position_m;
        fish.step(&bend, Vec3::ZERO);
        path += fish.point.position_m.distance(last);
        turned += level_turn_deg(prev, fish.heading());
        prev = fish.heading();
    }
    let secs = steps as f32 * dt;
    (
        path / secs,
        turned / secs,
        path / turned.to_radians().abs().max(1e-3) / 0.5,
    )
}

/// From a lead-in at `lead_fraction` of the top speed, a full bend with the
/// swim-MC at `speed_fraction` and `fins`: seconds to turn 90° and 180°, and
/// how far from where the bend began the fish is when it has turned 180°
/// (the loop's width), body lengths.
pub fn about_turn(lead_fraction: f32, speed_fraction: f32, fins: PectoralFins) -> (f32, f32, f32) {
    let mut fish = PhysicalFish::new(BodySpecies::Fish, 0.5, Vec3::ZERO, Vec3::X, 0.3);
    let dt = fish.body().dt_secs();
    let lead = MotorIntent {
        speed_fraction: lead_fraction,
        start_turn_deg: None,
        steer: 0.0,
        fins: PectoralFins::NEUTRAL,
    };
    for _ in 0..(6.0 / dt) as usize {
        fish.step(&lead, Vec3::ZERO);
    }
    let bend = MotorIntent {
        speed_fraction,
        steer: 1.0,
        fins,
        ..lead
    };
    let (start, from) = (fish.heading(), fish.point.position_m);
    let (mut turned, mut prev, mut t90) = (0.0f32, start, None);
    for step in 0..(30.0 / dt) as usize {
        fish.step(&bend, Vec3::ZERO);
        turned += level_turn_deg(prev, fish.heading());
        prev = fish.heading();
        if t90.is_none() && turned.abs() >= 90.0 {
            t90 = Some((step + 1) as f32 * dt);
        }
        if turned.abs() >= 180.0 {
            return (
                t90.unwrap_or(0.0),
                (step + 1) as f32 * dt,
                fish.point.position_m.distance(from) / 0.5,
            );
        }
    }
    (t90.unwrap_or(f32::NAN), f32::NAN, f32::NAN)
}
