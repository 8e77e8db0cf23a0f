//! Steering behaviours after Craig Reynolds, "Steering Behaviors For
//! Autonomous Characters" (GDC 1999).
//!
//! Each behaviour is a small free function that returns a steering
//! acceleration in m/s²; the caller adds several of them with weights, and
//! [`Fish::integrate`] limits the sum to a maximum force and the resulting
//! velocity to a speed range. Most behaviours follow Reynolds' recipe
//! `steering = desired velocity − current velocity`, read as an acceleration
//! that would reach the desired velocity in one second.
//!
//! The numbers of the recipe itself (the wander pitch's fade, the rock
//! algorithm's clearance, the longest prediction, the wall algorithm's gains)
//! are the calling world's [`SteeringTuning`]; [`SteeringParams`] holds the
//! slider-facing limits and weights.

use crate::sim::common::fmath;
use std::f32::consts::PI;

use glam::Vec3;
use rand::Rng;
use serde::{Deserialize, Serialize};

use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::Obstacle;
use crate::sim::common::steering_tuning::SteeringTuning;
use crate::sim::common::tank::Tank;

/// Tuning of the steering behaviours. Defaults make a calm aquarium of fish
/// about 0.3 m long; the app may expose them as sliders.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SteeringParams {
    /// Top speed in m/s. Default 0.8 m/s (≈ 2.7 body lengths/s): a brisk
    /// dart for a 0.3 m fish; faster looks frantic in a 12 m tank.
    pub max_speed_m_per_s: f32,
    /// Lowest speed in m/s. Default 0.15 m/s: fish keep swimming, and a
    /// moving fish always has a heading to turn with.
    pub min_speed_m_per_s: f32,
    /// Relaxed swimming speed in body lengths per second; wander aims for it.
    /// Default 1.5 /s: typical cruising of fish (0.45–0.75 m/s for the
    /// 0.3–0.5 m fish of the default scene), so bigger fish cruise a little faster.
    pub cruise_speed_body_lengths_per_s: f32,
    /// Largest steering acceleration in m/s². Default 1.5 m/s²: at 0.8 m/s
    /// the tightest turn has a radius of v²/a ≈ 0.43 m, about one body
    /// length, which looks agile but not robotic.
    pub max_force_m_per_s2: f32,
    /// How far ahead of the fish the wander circle sits, in metres.
    /// Default 1.0 m: with the radius below the wander target is at most
    /// atan(0.5/1.0) ≈ 27° off the heading, giving gentle curves.
    pub wander_distance_m: f32,
    /// Radius of the wander circle in metres. Default 0.5 m (see above).
    pub wander_radius_m: f32,
    /// Largest random change of the wander angle per step (at 60 steps/s), in
    /// radians. Default 0.2 rad: the target drifts around the circle in a
    /// few seconds, so paths meander without jittering.
    pub wander_jitter_rad: f32,
    /// Largest random change of the wander pitch per step, in radians.
    /// Default 0.06 rad: depth changes are gentler than turns.
    pub wander_pitch_jitter_rad: f32,
    /// Largest up/down tilt of the wander target, in radians. Default 0.35
    /// rad (20°): fish mostly swim level, gliding up and down a little.
    pub wander_max_pitch_rad: f32,
    /// Weight of wander in the sum (dimensionless). Default 1: the baseline.
    pub wander_weight: f32,
    /// Weight of tank containment (dimensionless). Default 2: walls win over
    /// wandering.
    pub containment_weight: f32,
    /// Weight of obstacle avoidance (dimensionless). Default 1.5: a rock
    /// first seen at the look-ahead distance gives a push of 0.8 × 1.5 =
    /// 1.2 m/s², just under the max force, and the push saturates as the
    /// gap closes, so the swerve starts gently and then wins over wandering.
    pub avoidance_weight: f32,
    /// How far ahead in time containment predicts the path, in seconds.
    /// Default 1.5 s: at top speed the fish reacts 1.2 m before the margin,
    /// more than twice its tightest turning radius.
    pub containment_look_ahead_s: f32,
    /// Distance from the glass, floor and surface that the predicted path
    /// must keep, in metres. Default 0.5 m: fish turn one to two body
    /// lengths before the glass and never need the hard rule.
    pub containment_margin_m: f32,
    /// How far ahead obstacle avoidance looks, in metres. Default 2.0 m:
    /// enough to pass the largest rock (1 m radius) with a smooth curve.
    pub avoidance_look_ahead_m: f32,
}

impl Default for SteeringParams {
    fn default() -> Self {
        Self {
            max_speed_m_per_s: 0.8,
            min_speed_m_per_s: 0.15,
            cruise_speed_body_lengths_per_s: 1.5,
            max_force_m_per_s2: 1.5,
            wander_distance_m: 1.0,
            wander_radius_m: 0.5,
            wander_jitter_rad: 0.2,
            wander_pitch_jitter_rad: 0.06,
            wander_max_pitch_rad: 0.35,
            wander_weight: 1.0,
            containment_weight: 2.0,
            avoidance_weight: 1.5,
            containment_look_ahead_s: 1.5,
            containment_margin_m: 0.5,
            avoidance_look_ahead_m: 2.0,
        }
    }
}

/// `v` shortened to at most `max_len` (longer vectors keep their direction).
/// A non-finite `v` gives zero and a negative or NaN `max_len` counts as 0,
/// so the result is always finite.
pub fn limit(v: Vec3, max_len: f32) -> Vec3 {
    let max_len = max_len.max(0.0);
    let len = v.length();
    if !len.is_finite() {
        Vec3::ZERO
    } else if len > max_len {
        v * (max_len / len)
    } else {
        v
    }
}

/// Seek: steer towards `target_m` at `max_speed_m_per_s`.
///
/// `desired = normalize(target − pos) · max_speed`, `steering = desired − vel`.
/// At the target itself the desired velocity is zero (so it brakes).
pub fn seek(pos_m: Vec3, vel_m_per_s: Vec3, target_m: Vec3, max_speed_m_per_s: f32) -> Vec3 {
    let desired_m_per_s = (target_m - pos_m).normalize_or_zero() * max_speed_m_per_s;
    desired_m_per_s - vel_m_per_s
}

/// Flee: steer straight away from `threat_m` at `max_speed_m_per_s`
/// (Lim & Tan's eq. 1 with the flee sign; docs/boids.md).
///
/// `desired = normalize(pos − threat) · max_speed`,
/// `steering = limit(desired − vel, max_force)`. A fish exactly at the threat
/// has no direction to flee in and gets zero desired velocity.
pub fn flee(
    pos_m: Vec3,
    vel_m_per_s: Vec3,
    threat_m: Vec3,
    max_speed_m_per_s: f32,
    max_force_m_per_s2: f32,
) -> Vec3 {
    let desired_m_per_s = (pos_m - threat_m).normalize_or_zero() * max_speed_m_per_s;
    limit(desired_m_per_s - vel_m_per_s, max_force_m_per_s2)
}

/// Arrive: seek `target_m`, slowing down inside `arrival_distance_m` so that the
/// fish stops at the target instead of overshooting (Lim & Tan, "arrival").
///
/// With `d = ‖target − pos‖`: `speed = max_speed · min(1, d / arrival_distance)`,
/// `desired = normalize(target − pos) · speed`,
/// `steering = limit(desired − vel, max_force)`. An arrival distance of zero or
/// less behaves like [`seek`] (limited).
pub fn arrive(
    pos_m: Vec3,
    vel_m_per_s: Vec3,
    target_m: Vec3,
    max_speed_m_per_s: f32,
    arrival_distance_m: f32,
    max_force_m_per_s2: f32,
) -> Vec3 {
    let offset_m = target_m - pos_m;
    let distance_m = offset_m.length();
    let ramp = if arrival_distance_m > 0.0 {
        (distance_m / arrival_distance_m).min(1.0)
    } else {
        1.0
    };
    let desired_m_per_s = offset_m.normalize_or_zero() * max_speed_m_per_s * ramp;
    limit(desired_m_per_s - vel_m_per_s, max_force_m_per_s2)
}

/// Where a target at `target_m` moving at `target_vel_m_per_s` will be when a
/// pursuer at `pos_m` (top speed `max_speed_m_per_s`) could reach it (Reynolds
/// 1999): `T = min(distance / max_speed, max_prediction)`,
/// `future = target + target_vel · T`, with `tuning`'s
/// [`SteeringTuning::max_prediction_s`].
pub fn predicted_position_m(
    pos_m: Vec3,
    target_m: Vec3,
    target_vel_m_per_s: Vec3,
    max_speed_m_per_s: f32,
    tuning: &SteeringTuning,
) -> Vec3 {
    let distance_m = pos_m.distance(target_m);
    let t_s = if max_speed_m_per_s > 0.0 {
        (distance_m / max_speed_m_per_s).min(tuning.max_prediction_s)
    } else {
        tuning.max_prediction_s
    };
    let future_m = target_m + target_vel_m_per_s * t_s;
    if future_m.is_finite() {
        future_m
    } else {
        target_m
    }
}

/// Pursue: seek where the target is going to be, not where it is (Reynolds
/// 1999): `steering = limit(seek(pos, vel, predicted_position_m(…), max_speed), max_force)`.
/// A shark uses it to cut a fleeing fish off.
pub fn pursue(
    pos_m: Vec3,
    vel_m_per_s: Vec3,
    target_m: Vec3,
    target_vel_m_per_s: Vec3,
    max_speed_m_per_s: f32,
    max_force_m_per_s2: f32,
    tuning: &SteeringTuning,
) -> Vec3 {
    let future_m = predicted_position_m(
        pos_m,
        target_m,
        target_vel_m_per_s,
        max_speed_m_per_s,
        tuning,
    );
    limit(
        seek(pos_m, vel_m_per_s, future_m, max_speed_m_per_s),
        max_force_m_per_s2,
    )
}

/// Evade: flee from where the threat is going to be (Reynolds 1999):
/// `steering = flee(pos, vel, predicted_position_m(…), max_speed, max_force)`,
/// the prediction using the threat's own top speed would be more exact but the
/// fish only knows its own, as in Reynolds' formulation.
pub fn evade(
    pos_m: Vec3,
    vel_m_per_s: Vec3,
    threat_m: Vec3,
    threat_vel_m_per_s: Vec3,
    max_speed_m_per_s: f32,
    max_force_m_per_s2: f32,
    tuning: &SteeringTuning,
) -> Vec3 {
    let future_m = predicted_position_m(
        pos_m,
        threat_m,
        threat_vel_m_per_s,
        max_speed_m_per_s,
        tuning,
    );
    flee(
        pos_m,
        vel_m_per_s,
        future_m,
        max_speed_m_per_s,
        max_force_m_per_s2,
    )
}

/// Wall following, Lim & Tan's wall algorithm (SIMBA paper Figs 3–5;
/// `docs/boids.md`): steer along the wall instead of reversing.
///
/// The paper works in 2-D with a wall from A to B: `norm = normalise(A − B)`,
/// `dir = (norm.y, −norm.x)`, `a1 = forward·dir`, `a2 = forward·norm`,
/// `dv = −a1·dir·k1 + a2·norm·k2`, `steering = dv − forward`. Here, in 3-D,
/// `wall_normal` is the unit normal pointing *out of the water into the wall*
/// (the paper's `dir`, up to a sign that cancels in `a1·dir`), the
/// along-the-wall part is everything of the velocity that is not along the
/// normal (the paper's `a2·norm`, now including up and down):
///
/// - `a1 = vel·n`, `along = vel − a1·n`;
/// - if the along part is (nearly) zero — a fish swimming straight at the
///   glass — it is replaced by `tie_break` (the caller passes e.g. the
///   direction along the wall towards open water) so the fish turns instead of
///   reversing;
/// - `dv = −a1·n·k1 + along·k2`, rescaled to the current speed (a turn, not a
///   brake), `steering = limit(dv − vel, max_force)`.
///
/// Applied only when the fish is within `range_m` of the wall
/// (`distance_m < range_m`) and heading in (`a1 > 0`); zero otherwise. Because
/// the force has no component along the wall (for k2 = 1), the fish's
/// velocity along the wall keeps its sign while the into-the-wall part turns
/// round: it ends up parallel to the wall or leaving it.
#[allow(clippy::too_many_arguments)]
pub fn follow_wall(
    vel_m_per_s: Vec3,
    wall_normal: Vec3,
    distance_m: f32,
    range_m: f32,
    tie_break: Vec3,
    k_away: f32,
    k_along: f32,
    max_force_m_per_s2: f32,
) -> Vec3 {
    let a1 = vel_m_per_s.dot(wall_normal);
    if !(distance_m < range_m && a1 > 0.0) {
        return Vec3::ZERO;
    }
    let speed_m_per_s = vel_m_per_s.length();
    let mut along_m_per_s = vel_m_per_s - wall_normal * a1;
    if along_m_per_s.length() < 0.05 * speed_m_per_s {
        let side = tie_break - wall_normal * tie_break.dot(wall_normal);
        along_m_per_s = side.normalize_or_zero() * speed_m_per_s;
    }
    let dv_m_per_s = -wall_normal * a1 * k_away + along_m_per_s * k_along;
    let desired_m_per_s = dv_m_per_s.normalize_or_zero() * speed_m_per_s;
    limit(desired_m_per_s - vel_m_per_s, max_force_m_per_s2)
}

/// The six faces of the water around `pos_m`: each face's outward normal (out
/// of the water, into the glass, sand or surface) and its distance from
/// `pos_m`, in the order −x, +x, −y, +y, −z, +z.
fn water_faces(pos_m: Vec3, tank: &Tank) -> [(Vec3, f32); 6] {
    [
        (Vec3::NEG_X, pos_m.x - tank.min_m.x),
        (Vec3::X, tank.max_m.x - pos_m.x),
        (Vec3::NEG_Y, pos_m.y - tank.min_m.y),
        (Vec3::Y, tank.max_m.y - pos_m.y),
        (Vec3::NEG_Z, pos_m.z - tank.min_m.z),
        (Vec3::Z, tank.max_m.z - pos_m.z),
    ]
}

/// [`follow_wall`] summed over `faces` (normal, distance), each turn limited to
/// `max_force_per_face_m_per_s2` and multiplied by `strength(distance)`, with
/// `tuning`'s gains k1 and k2 ([`SteeringTuning::wall_away_gain`],
/// [`SteeringTuning::wall_along_gain`]).
fn follow_faces(
    vel_m_per_s: Vec3,
    faces: impl IntoIterator<Item = (Vec3, f32)>,
    range_m: f32,
    tie_break: Vec3,
    max_force_per_face_m_per_s2: f32,
    tuning: &SteeringTuning,
    strength: impl Fn(f32) -> f32,
) -> Vec3 {
    faces
        .into_iter()
        .map(|(normal, distance_m)| {
            follow_wall(
                vel_m_per_s,
                normal,
                distance_m,
                range_m,
                tie_break,
                tuning.wall_away_gain,
                tuning.wall_along_gain,
                max_force_per_face_m_per_s2,
            ) * strength(distance_m)
        })
        .fold(Vec3::ZERO, |sum, turn| sum + turn)
}

/// The four vertical glass walls by [`follow_wall`]: for each wall within
/// `range_m` that the animal heads into, a turn along it (two at a corner,
/// summed), at most `max_force_m_per_s2`. The tie-break for an animal aimed
/// straight at the glass is the direction along the wall towards the middle of
/// the tank, so one in a corner turns out of it.
pub fn glass_walls(
    pos_m: Vec3,
    vel_m_per_s: Vec3,
    tank: &Tank,
    range_m: f32,
    max_force_m_per_s2: f32,
    tuning: &SteeringTuning,
) -> Vec3 {
    let to_middle = (tank.center_m() - pos_m) * Vec3::new(1.0, 0.0, 1.0);
    let glass = water_faces(pos_m, tank)
        .into_iter()
        .filter(|(normal, _)| normal.y == 0.0);
    let steering = follow_faces(
        vel_m_per_s,
        glass,
        range_m,
        to_middle,
        max_force_m_per_s2,
        tuning,
        |_| 1.0,
    );
    limit(steering, max_force_m_per_s2)
}

/// Wall avoidance of the boid layer: Lim & Tan's wall algorithm ([`follow_wall`],
/// SIMBA Figs 3–5) for each of the six faces of the water (four panes of glass,
/// the sand and the surface) that the fish is within `range_m` of and heading
/// into, each scaled like the rock algorithm by the remaining range,
/// `range_m / max(gap, min_wall_gap)` ([`SteeringTuning::min_wall_gap_m`]), so
/// the fish turns gently far off and
/// hard close in. The tie-break for a fish aimed straight at a face is the
/// direction along it towards the middle of the tank. Returns a velocity change
/// (m/s), unlimited: the caller turns it into a force and limits it.
pub fn avoid_walls(
    pos_m: Vec3,
    vel_m_per_s: Vec3,
    tank: &Tank,
    range_m: f32,
    tuning: &SteeringTuning,
) -> Vec3 {
    let steering = follow_faces(
        vel_m_per_s,
        water_faces(pos_m, tank),
        range_m,
        tank.center_m() - pos_m,
        f32::INFINITY,
        tuning,
        |distance_m| range_m / distance_m.max(tuning.min_wall_gap_m),
    );
    if steering.is_finite() {
        steering
    } else {
        Vec3::ZERO
    }
}

/// Containment of the boid layer: [`glass_walls`] (Lim & Tan's wall
/// algorithm) plus the floor and surface handling of [`containment`] (pitch up
/// or down, from `params`' look-ahead and margin), at most `max_force_m_per_s2`.
pub fn contain_in_tank(
    pos_m: Vec3,
    vel_m_per_s: Vec3,
    tank: &Tank,
    range_m: f32,
    params: &SteeringParams,
    max_force_m_per_s2: f32,
    tuning: &SteeringTuning,
) -> Vec3 {
    let walls = glass_walls(
        pos_m,
        vel_m_per_s,
        tank,
        range_m,
        max_force_m_per_s2,
        tuning,
    );
    let vertical = floor_and_surface(
        pos_m,
        vel_m_per_s,
        tank,
        params.containment_look_ahead_s,
        params.containment_margin_m,
        params.max_speed_m_per_s,
    );
    limit(walls + vertical, max_force_m_per_s2)
}

/// Wander: Reynolds' random but smooth swimming.
///
/// A circle of radius `wander_radius_m` lies `wander_distance_m` ahead of the
/// fish, along its horizontal heading tilted up or down by `wander_pitch_rad`.
/// A target point on the circle, at `wander_angle_rad` around it, moves a
/// little at random each step; the fish seeks it at its cruising speed:
///
/// `angle += U(−jitter, jitter)`,
/// `pitch = clamp((pitch + U(−pj, pj)) · (1 − fade), ±max)`,
/// `target = pos + d·(cos pitch·fwd + sin pitch·up) + r·(cos angle·fwd + sin angle·side)`,
/// `steering = seek(pos, vel, target, cruise_speed)`.
///
/// The circle is level and the pitch small and fading, so fish swim mostly
/// level, gliding slowly up and down (the fade is `tuning`'s
/// [`SteeringTuning::wander_pitch_fade_per_step`]). Updates the fish's wander
/// angles.
pub fn wander(
    fish: &mut Fish,
    rng: &mut impl Rng,
    params: &SteeringParams,
    tuning: &SteeringTuning,
) -> Vec3 {
    let angle_rad = fish.wander_angle_rad + signed_unit(rng) * params.wander_jitter_rad;
    let pitch_rad = (fish.wander_pitch_rad + signed_unit(rng) * params.wander_pitch_jitter_rad)
        * (1.0 - tuning.wander_pitch_fade_per_step);
    let max_pitch_rad = params.wander_max_pitch_rad.abs();
    // Angle wrapped to −π..π, pitch clamped; a NaN from a broken slider resets to 0.
    fish.wander_angle_rad = finite_or_zero((angle_rad + PI).rem_euclid(2.0 * PI) - PI);
    fish.wander_pitch_rad = finite_or_zero(pitch_rad.max(-max_pitch_rad).min(max_pitch_rad));

    let forward = (fish.heading() * Vec3::new(1.0, 0.0, 1.0)).normalize_or(Vec3::X);
    let side = forward.cross(Vec3::Y);
    let (sin_pitch, cos_pitch) = fmath::sin_cos(fish.wander_pitch_rad);
    let (sin_angle, cos_angle) = fmath::sin_cos(fish.wander_angle_rad);
    let circle_center_m =
        fish.position_m + (cos_pitch * forward + sin_pitch * Vec3::Y) * params.wander_distance_m;
    let target_m =
        circle_center_m + (cos_angle * forward + sin_angle * side) * params.wander_radius_m;

    let cruise_m_per_s = params.cruise_speed_body_lengths_per_s * fish.body_length_m;
    seek(
        fish.position_m,
        fish.velocity_m_per_s,
        target_m,
        cruise_m_per_s,
    )
}

/// Containment: turn away from the glass, the floor and the water surface
/// before reaching them.
///
/// Predict `future = pos + vel · look_ahead_s`. If it is inside the tank
/// shrunk by `margin_m`, return zero. Otherwise the fish turns the way real
/// fish do, each turn at full strength and perpendicular to its heading:
///
/// - if `future` is too close to the glass, turn left or right towards open
///   water: `m` = horizontal direction from the fish to the middle of the
///   tank, `f` = horizontal heading, `yaw = normalize(m − (m·f) f)`;
/// - if it is too close to the floor or surface, pitch up or down:
///   `u` = ±y towards the safe height, `h` = heading,
///   `pitch = normalize(u − (u·h) h)`;
/// - `steering = (yaw + pitch) · max_speed`.
///
/// Turning instead of braking keeps the fish moving (fish do not swim
/// backwards). Aiming at fixed goals (the middle, up or down) rather than at
/// the nearest wall means a fish in a corner never dithers between two
/// walls. A fish aimed exactly away from the goal turns to its right.
pub fn containment(
    pos_m: Vec3,
    vel_m_per_s: Vec3,
    tank: &Tank,
    look_ahead_s: f32,
    margin_m: f32,
    max_speed_m_per_s: f32,
) -> Vec3 {
    let future_m = pos_m + vel_m_per_s * look_ahead_s;
    let safe_m = tank.clamp_inside(future_m, margin_m);
    let right = horizontal_side(vel_m_per_s);
    let flat = Vec3::new(1.0, 0.0, 1.0);

    let near_glass = future_m.x != safe_m.x || future_m.z != safe_m.z;
    let yaw = if near_glass {
        let to_middle = ((tank.center_m() - pos_m) * flat).normalize_or_zero();
        turn_towards(to_middle, (vel_m_per_s * flat).normalize_or_zero(), right)
    } else {
        Vec3::ZERO
    };
    yaw * max_speed_m_per_s
        + floor_and_surface(
            pos_m,
            vel_m_per_s,
            tank,
            look_ahead_s,
            margin_m,
            max_speed_m_per_s,
        )
}

/// The floor-and-surface half of [`containment`]: if the path predicted
/// `look_ahead_s` ahead comes within `margin_m` of the sand or the surface,
/// pitch up or down, perpendicular to the heading:
/// `u` = ±y towards the safe height, `h` = heading,
/// `steering = normalize(u − (u·h) h) · max_speed`; zero otherwise.
pub fn floor_and_surface(
    pos_m: Vec3,
    vel_m_per_s: Vec3,
    tank: &Tank,
    look_ahead_s: f32,
    margin_m: f32,
    max_speed_m_per_s: f32,
) -> Vec3 {
    let future_m = pos_m + vel_m_per_s * look_ahead_s;
    let safe_m = tank.clamp_inside(future_m, margin_m);
    if future_m.y == safe_m.y {
        return Vec3::ZERO;
    }
    let up_or_down = Vec3::Y * (safe_m.y - future_m.y).signum();
    turn_towards(
        up_or_down,
        vel_m_per_s.normalize_or_zero(),
        horizontal_side(vel_m_per_s),
    ) * max_speed_m_per_s
}

/// The unit direction, perpendicular to `heading`, in which the heading must
/// rotate to point at `goal`: `normalize(goal − (goal·heading) heading)`, or
/// `tie_break` if `goal` is straight ahead or behind, or zero if `goal` is.
fn turn_towards(goal: Vec3, heading: Vec3, tie_break: Vec3) -> Vec3 {
    if goal == Vec3::ZERO {
        return Vec3::ZERO;
    }
    (goal - heading * goal.dot(heading)).normalize_or(tie_break)
}

/// Obstacle avoidance: sway around the nearest obstacle in the path, Lim &
/// Tan's rock algorithm (SIMBA paper Figs 6–7; docs/boids.md):
/// "steer along the agent's right (or left) vector with a force inversely
/// proportional to the remaining range", so the fish sways instead of
/// reversing.
///
/// An obstacle is "in the path" if its core (a rock's centre, or the point of
/// a pillar's or polygon's axis at the fish's height) lies ahead, no further
/// than `look_ahead_m` plus its (bounding) radius, and the straight path passes
/// closer to the core than radius + `clearance_m`. For the one whose surface is
/// nearest, with `offset` the vector from the path to the core (perpendicular
/// to the velocity: the fish's right or left, or up over a low rock) and `d`
/// the remaining range (the current distance to its surface):
///
/// `steering = normalize(−offset) · max_speed · look_ahead_m / max(d, 0.1 m)`
///
/// A fish aimed exactly at the core sways to its right. The push has no
/// backward component, and it is not limited here: the caller limits the sum.
pub fn avoid_obstacles<'a>(
    pos_m: Vec3,
    vel_m_per_s: Vec3,
    obstacles: impl IntoIterator<Item = &'a Obstacle>,
    look_ahead_m: f32,
    clearance_m: f32,
    max_speed_m_per_s: f32,
) -> Vec3 {
    /// Smallest distance used in the strength formula, in metres: keeps the
    /// push finite when a fish touches the surface.
    const MIN_GAP_M: f32 = 0.1;

    let direction = vel_m_per_s.normalize_or_zero();
    if direction == Vec3::ZERO {
        return Vec3::ZERO;
    }
    // (distance to surface, offset from path to core) of the nearest threat.
    let mut nearest: Option<(f32, Vec3)> = None;
    for obstacle in obstacles {
        let radius_m = obstacle.radius_m();
        // Quick reject (most fish, most obstacles): too far to matter.
        let reach_m = look_ahead_m + 2.0 * radius_m + clearance_m;
        let center = obstacle.footprint_center_m();
        let (dx, dz) = (pos_m.x - center.x, pos_m.z - center.y);
        if dx * dx + dz * dz > reach_m * reach_m {
            continue;
        }
        let to_core_m = obstacle.core_point_m(pos_m) - pos_m;
        let ahead_m = to_core_m.dot(direction);
        let offset_m = to_core_m - direction * ahead_m;
        let in_path = ahead_m > 0.0
            && ahead_m <= look_ahead_m + radius_m
            && offset_m.length() < radius_m + clearance_m;
        if !in_path {
            continue;
        }
        let gap_m = obstacle.signed_distance_m(pos_m);
        if nearest.is_none_or(|(nearest_gap_m, _)| gap_m < nearest_gap_m) {
            nearest = Some((gap_m, offset_m));
        }
    }
    let Some((gap_m, offset_m)) = nearest else {
        return Vec3::ZERO;
    };
    let away = (-offset_m).normalize_or(horizontal_side(direction));
    away * max_speed_m_per_s * look_ahead_m / gap_m.max(MIN_GAP_M)
}

/// The horizontal direction to the right of `v` (`v × up`), or +z if `v` is
/// vertical or zero. Used to break ties when a fish swims straight at
/// something.
fn horizontal_side(v: Vec3) -> Vec3 {
    v.cross(Vec3::Y).normalize_or(Vec3::Z)
}

/// `x` if it is a finite number, else 0.
fn finite_or_zero(x: f32) -> f32 {
    if x.is_finite() { x } else { 0.0 }
}

/// A uniform random number in [−1, 1). Multiplying it by a jitter never
/// panics, unlike building a range from a user-set value.
fn signed_unit(rng: &mut impl Rng) -> f32 {
    rng.random::<f32>() * 2.0 - 1.0
}

#[cfg(test)]
mod tests {
    use crate::sim::boids::world::DT_SECS;
    use crate::sim::common::steering::*;
    use rand::SeedableRng;

    /// The steering layer's default tuning.
    fn tuning() -> SteeringTuning {
        SteeringTuning::default()
    }
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn limit_shortens_long_vectors_only_and_is_never_nan() {
        assert_eq!(
            limit(Vec3::new(3.0, 4.0, 0.0), 1.0),
            Vec3::new(0.6, 0.8, 0.0)
        );
        assert_eq!(limit(Vec3::X * 0.5, 1.0), Vec3::X * 0.5);
        assert_eq!(limit(Vec3::INFINITY, 1.0), Vec3::ZERO);
        assert_eq!(limit(Vec3::X, -1.0), Vec3::ZERO);
    }

    #[test]
    fn seek_points_from_current_to_desired_velocity() {
        let steer = seek(Vec3::ZERO, Vec3::X, Vec3::new(0.0, 0.0, 5.0), 2.0);
        assert_eq!(steer, Vec3::new(-1.0, 0.0, 2.0));
        assert_eq!(seek(Vec3::ONE, Vec3::ZERO, Vec3::ONE, 2.0), Vec3::ZERO);
    }

    #[test]
    fn wander_keeps_a_fish_swimming_mostly_level() {
        let params = SteeringParams::default();
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let mut fish = Fish::new(Vec3::ZERO, Vec3::X * 0.4, 0.3, 0.0);
        let mut max_climb: f32 = 0.0;
        let mut turned = false;
        for _ in 0..3_600 {
            let steer = wander(&mut fish, &mut rng, &params, &tuning());
            fish.integrate(steer, &params, DT_SECS);
            max_climb = max_climb.max(fish.heading().y.abs());
            turned |= fish.heading().x < 0.0;
        }
        assert!(max_climb < 0.5, "climb angle too steep: sin = {max_climb}");
        assert!(
            turned,
            "a wandering fish should change direction in a minute"
        );
    }

    /// Swims a fish with `steer` (soft steering only, no hard constraints)
    /// for `secs` seconds and returns its path.
    fn swim(mut fish: Fish, secs: f32, mut steer: impl FnMut(&mut Fish) -> Vec3) -> Vec<Fish> {
        let params = SteeringParams::default();
        let steps = (secs / DT_SECS) as usize;
        (0..steps)
            .map(|_| {
                let steering = steer(&mut fish);
                fish.integrate(steering, &params, DT_SECS);
                fish
            })
            .collect()
    }

    /// Weighted containment with the default parameters.
    fn contain(fish: &Fish, tank: &Tank) -> Vec3 {
        let p = SteeringParams::default();
        containment(
            fish.position_m,
            fish.velocity_m_per_s,
            tank,
            p.containment_look_ahead_s,
            p.containment_margin_m,
            p.max_speed_m_per_s,
        ) * p.containment_weight
    }

    /// Weighted obstacle avoidance with the default parameters.
    fn avoid(fish: &Fish, obstacles: &[Obstacle]) -> Vec3 {
        let p = SteeringParams::default();
        avoid_obstacles(
            fish.position_m,
            fish.velocity_m_per_s,
            obstacles,
            p.avoidance_look_ahead_m,
            tuning().avoidance_clearance_m,
            p.max_speed_m_per_s,
        ) * p.avoidance_weight
    }

    /// Smallest signed distance between the path and the obstacle, metres.
    fn min_gap_m(path: &[Fish], obstacle: &Obstacle) -> f32 {
        path.iter()
            .map(|f| obstacle.signed_distance_m(f.position_m))
            .fold(f32::INFINITY, f32::min)
    }

    #[test]
    fn fish_heading_straight_at_a_rock_swerves_before_touching_it() {
        let rock = [Obstacle::Rock {
            center_m: Vec3::new(4.0, 1.0, 0.0),
            radius_m: 1.0,
        }];
        let start = Fish::new(Vec3::new(0.0, 1.0, 0.0), Vec3::X * 0.8, 0.3, 0.0);
        let path = swim(start, 15.0, |f| avoid(f, &rock));
        let gap_m = min_gap_m(&path, &rock[0]);
        assert!(gap_m > 0.0, "touched the rock: gap {gap_m} m");
        let end_x_m = path.last().map(|f| f.position_m.x).unwrap_or_default();
        assert!(end_x_m > 6.0, "did not get past the rock: x = {end_x_m}");
    }

    #[test]
    fn fish_heading_straight_at_a_pillar_swerves_before_touching_it() {
        let pillar = [Obstacle::Cylinder {
            base_center_m: Vec3::new(0.0, 0.0, 3.0),
            radius_m: 0.5,
            height_m: 3.0,
        }];
        let start = Fish::new(Vec3::new(0.0, 1.5, 0.0), Vec3::Z * 0.8, 0.3, 0.0);
        let path = swim(start, 15.0, |f| avoid(f, &pillar));
        let gap_m = min_gap_m(&path, &pillar[0]);
        assert!(gap_m > 0.0, "touched the pillar: gap {gap_m} m");
    }

    #[test]
    fn fish_heading_straight_at_a_wall_turns_back_before_reaching_it() {
        let tank = Tank::default();
        let start = Fish::new(Vec3::new(0.0, 2.0, 0.0), Vec3::X * 0.8, 0.3, 0.0);
        let path = swim(start, 30.0, |f| contain(f, &tank));
        let max_x_m = path.iter().map(|f| f.position_m.x).fold(f32::MIN, f32::max);
        assert!(
            max_x_m < tank.max_m.x - 0.2,
            "within 0.2 m of the glass: x = {max_x_m}"
        );
        assert!(path.iter().all(|f| tank.contains(f.position_m, 0.1)));
        assert!(
            path.iter().any(|f| f.velocity_m_per_s.x < -0.5),
            "never swam back"
        );
    }

    #[test]
    fn fish_diving_at_the_floor_levels_out_above_the_sand() {
        let tank = Tank::default();
        let start = Fish::new(Vec3::new(0.0, 2.0, 0.0), Vec3::NEG_Y * 0.8, 0.3, 0.0);
        let path = swim(start, 10.0, |f| contain(f, &tank));
        let min_y_m = path.iter().map(|f| f.position_m.y).fold(f32::MAX, f32::min);
        assert!(min_y_m > 0.2, "within 0.2 m of the sand: y = {min_y_m}");
    }

    #[test]
    fn wandering_fish_never_touch_the_glass_with_soft_steering_alone() {
        let params = SteeringParams::default();
        let tank = Tank::default();
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        for _ in 0..40 {
            let u = Vec3::new(rng.random(), rng.random(), rng.random());
            let position_m = tank.min_m + Vec3::splat(0.6) + u * (tank.size_m() - 1.2);
            let yaw_rad = rng.random::<f32>() * 2.0 * PI;
            let velocity = Vec3::new(fmath::cos(yaw_rad), 0.0, fmath::sin(yaw_rad)) * 0.8;
            let start = Fish::new(position_m, velocity, 0.3, 0.0);
            let path = swim(start, 60.0, |f| {
                wander(f, &mut rng, &params, &tuning()) * params.wander_weight + contain(f, &tank)
            });
            for fish in &path {
                let p = fish.position_m;
                assert!(tank.contains(p, 0.1), "too close to the glass: {p}");
            }
        }
    }

    #[test]
    fn flee_points_straight_away_from_the_threat_at_most_max_force() {
        let steer = flee(Vec3::ZERO, Vec3::ZERO, Vec3::new(1.0, 0.0, 0.0), 0.8, 10.0);
        assert!((steer - Vec3::new(-0.8, 0.0, 0.0)).length() < 1e-6);
        // Swimming towards the threat: turn round, limited to the max force.
        let steer = flee(Vec3::ZERO, Vec3::X * 0.8, Vec3::X, 0.8, 1.0);
        assert!((steer - Vec3::NEG_X).length() < 1e-6);
        // Already fleeing at full speed: nothing to change.
        let calm = flee(Vec3::ZERO, Vec3::NEG_X * 0.8, Vec3::X, 0.8, 1.0);
        assert!(calm.length() < 1e-6);
        // At the threat itself there is no way to flee: brake, never NaN.
        assert!(flee(Vec3::ONE, Vec3::Z, Vec3::ONE, 0.8, 1.0).is_finite());
    }

    #[test]
    fn arrive_slows_down_inside_the_arrival_distance_and_stops_at_the_target() {
        let target = Vec3::new(4.0, 0.0, 0.0);
        // Far away it is seek.
        let far = arrive(Vec3::ZERO, Vec3::ZERO, target, 0.8, 1.0, 10.0);
        assert!((far - Vec3::X * 0.8).length() < 1e-6);
        // At half the arrival distance it asks for half speed.
        let near = arrive(Vec3::new(3.5, 0.0, 0.0), Vec3::ZERO, target, 0.8, 1.0, 10.0);
        assert!((near - Vec3::X * 0.4).length() < 1e-6);
        // A fish swimming on at full speed near the target brakes.
        let braking = arrive(
            Vec3::new(3.5, 0.0, 0.0),
            Vec3::X * 0.8,
            target,
            0.8,
            1.0,
            10.0,
        );
        assert!(braking.x < 0.0);
        // Followed step by step, it comes to rest at the target; it may
        // overshoot a little (the steering is a spring of one second), but by
        // much less than the arrival distance.
        let params = SteeringParams {
            min_speed_m_per_s: 0.0,
            max_force_m_per_s2: 2.0,
            ..SteeringParams::default()
        };
        let mut fish = Fish::new(Vec3::ZERO, Vec3::X * 0.5, 0.3, 0.0);
        let mut max_x_m: f32 = 0.0;
        for _ in 0..1_200 {
            let steer = arrive(
                fish.position_m,
                fish.velocity_m_per_s,
                target,
                0.8,
                1.0,
                params.max_force_m_per_s2,
            );
            fish.integrate(steer, &params, DT_SECS);
            max_x_m = max_x_m.max(fish.position_m.x);
        }
        assert!(
            fish.position_m.distance(target) < 0.05,
            "{}",
            fish.position_m
        );
        assert!(max_x_m < target.x + 0.35, "overshot to {max_x_m}");
    }

    #[test]
    fn pursue_aims_ahead_of_a_moving_target_and_evade_away_from_where_it_will_be() {
        // A target 2 m ahead crossing sideways at 1 m/s: the pursuer (top speed
        // 1 m/s) predicts 2 s ahead and aims 2 m to the side.
        let (pos, target, target_vel) = (Vec3::ZERO, Vec3::X * 2.0, Vec3::Z);
        assert!(
            (predicted_position_m(pos, target, target_vel, 1.0, &tuning())
                - Vec3::new(2.0, 0.0, 2.0))
            .length()
                < 1e-6
        );
        let chase = pursue(pos, Vec3::ZERO, target, target_vel, 1.0, 10.0, &tuning());
        assert!(chase.x > 0.0 && chase.z > 0.0, "leads the target: {chase}");
        assert!(
            (chase.x - chase.z).abs() < 1e-5,
            "aims at (2, 0, 2): {chase}"
        );
        // Seeking the target itself would not lead it.
        assert!(seek(pos, Vec3::ZERO, target, 1.0).z.abs() < 1e-6);
        // Evade flees the predicted position: away in x, and away from +z.
        let escape = evade(pos, Vec3::ZERO, target, target_vel, 1.0, 10.0, &tuning());
        assert!(escape.x < 0.0 && escape.z < 0.0, "{escape}");
        // The prediction is bounded, so a far target is not extrapolated forever.
        let far = predicted_position_m(pos, Vec3::X * 100.0, Vec3::Z, 1.0, &tuning());
        assert!((far.z - tuning().max_prediction_s).abs() < 1e-5);
        // Limits hold.
        assert!(
            pursue(pos, Vec3::NEG_X, target, target_vel, 1.0, 0.5, &tuning()).length()
                <= 0.5 + 1e-6
        );
    }

    #[test]
    fn a_fish_near_a_wall_turns_along_it_instead_of_reversing() {
        // Lim & Tan's wall algorithm: a fish swimming at 45° into the +x glass
        // keeps its along-the-wall velocity (+z) and turns its into-the-wall
        // velocity round, ending up along the wall or leaving it.
        let tank = Tank::default();
        let params = SteeringParams {
            max_force_m_per_s2: 2.0,
            ..SteeringParams::default()
        };
        let start = Fish::new(
            Vec3::new(tank.max_m.x - 1.2, 2.0, -2.0),
            Vec3::new(0.5, 0.0, 0.5),
            0.3,
            0.0,
        );
        let path = swim(start, 4.0, |f| {
            glass_walls(
                f.position_m,
                f.velocity_m_per_s,
                &tank,
                1.5,
                params.max_force_m_per_s2,
                &tuning(),
            )
        });
        for fish in &path {
            assert!(fish.velocity_m_per_s.z > 0.0, "reversed along the wall");
            assert!(fish.position_m.x < tank.max_m.x - 0.1, "hit the glass");
        }
        let end = path.last().map(|f| f.velocity_m_per_s).unwrap_or_default();
        assert!(end.x <= 0.05, "still heading into the glass: {end}");
        assert!(end.z > 0.3, "not swimming along the glass: {end}");
        // Straight at the glass, it turns towards the middle of the tank
        // rather than bouncing straight back.
        let head_on = follow_wall(Vec3::X * 0.8, Vec3::X, 0.5, 1.5, Vec3::Z, 0.3, 1.0, 100.0);
        let turned = Vec3::X * 0.8 + head_on;
        assert!(turned.z > 0.7 && turned.x < 0.3, "{turned}");
        // Out of range or heading away: no force.
        assert_eq!(
            follow_wall(Vec3::X, Vec3::X, 2.0, 1.5, Vec3::Z, 0.3, 1.0, 1.0),
            Vec3::ZERO
        );
        assert_eq!(
            follow_wall(Vec3::NEG_X, Vec3::X, 0.5, 1.5, Vec3::Z, 0.3, 1.0, 1.0),
            Vec3::ZERO
        );
    }
}
