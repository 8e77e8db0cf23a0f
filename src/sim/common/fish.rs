//! One fish: where it is, how fast it swims, and how it moves under a
//! steering acceleration (a "point-mass vehicle" in Craig Reynolds' sense).

use std::f32::consts::TAU;

use glam::Vec3;
use serde::{Deserialize, Serialize};

use crate::sim::common::steering::{SteeringParams, limit};

/// Tail beats per second of a fish that is barely moving, in hertz.
/// Default 1.5 Hz: a resting fish still fans its tail slowly, so the renderer
/// never shows a frozen fish.
pub const TAIL_BEAT_BASE_HZ: f32 = 1.5;

/// Extra tail beats per body length travelled (dimensionless, 1/body length).
/// Default 3: real fish beat faster the faster they swim relative to their
/// size (Bainbridge 1958 measured roughly 1.3 beats per body length); we
/// exaggerate it so the speed difference is easy to see on screen.
pub const TAIL_BEATS_PER_BODY_LENGTH: f32 = 3.0;

/// Speeds below this (m/s) count as "not moving" for [`Fish::heading`].
/// Default 1e-6 m/s: far below anything visible, well above rounding noise.
const STILL_SPEED_M_PER_S: f32 = 1e-6;

/// A single fish, treated as a point with a velocity.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Fish {
    /// Centre of the body in metres.
    pub position_m: Vec3,
    /// Velocity in metres per second; the fish faces along it.
    pub velocity_m_per_s: Vec3,
    /// Nose-to-tail length in metres (0.3–0.5 m in the default scene).
    pub body_length_m: f32,
    /// Colour for the renderer, 0..1 around the colour wheel.
    pub hue: f32,
    /// Horizontal angle of the wander target on the wander circle, radians
    /// (0 = straight ahead). Drifts randomly; see `steering::wander`.
    pub wander_angle_rad: f32,
    /// Small up/down tilt of the wander target, radians (0 = level).
    pub wander_pitch_rad: f32,
    /// Phase of the tail beat, radians in 0..2π; the renderer bends the tail
    /// by something like sin(tail_phase_rad).
    pub tail_phase_rad: f32,
}

impl Fish {
    /// A fish at `position_m` swimming with `velocity_m_per_s`, wander state
    /// and tail phase at zero.
    pub fn new(position_m: Vec3, velocity_m_per_s: Vec3, body_length_m: f32, hue: f32) -> Self {
        Self {
            position_m,
            velocity_m_per_s,
            body_length_m,
            hue,
            wander_angle_rad: 0.0,
            wander_pitch_rad: 0.0,
            tail_phase_rad: 0.0,
        }
    }

    /// Unit vector the fish faces: its direction of motion, or +x when it is
    /// (almost) still. Never NaN.
    pub fn heading(&self) -> Vec3 {
        heading_of(self.velocity_m_per_s)
    }

    /// Current speed in metres per second.
    pub fn speed_m_per_s(&self) -> f32 {
        self.velocity_m_per_s.length()
    }

    /// Tail-beat frequency in hertz: base rate plus a part proportional to
    /// speed in body lengths per second,
    /// `f = TAIL_BEAT_BASE_HZ + TAIL_BEATS_PER_BODY_LENGTH · speed / body_length`.
    /// (A body shorter than 1 cm counts as 1 cm, so a zero length cannot
    /// divide by zero.)
    pub fn tail_beat_hz(&self) -> f32 {
        let body_length_m = self.body_length_m.max(0.01);
        TAIL_BEAT_BASE_HZ + TAIL_BEATS_PER_BODY_LENGTH * self.speed_m_per_s() / body_length_m
    }

    /// Advance the tail phase by `2π · f · dt`, kept in 0..2π.
    pub fn advance_tail_phase(&mut self, dt_secs: f32) {
        let phase = self.tail_phase_rad + TAU * self.tail_beat_hz() * dt_secs;
        self.tail_phase_rad = if phase.is_finite() {
            phase.rem_euclid(TAU)
        } else {
            0.0
        };
    }

    /// Move the fish one step of `dt_secs` under `steering_m_per_s2`
    /// (semi-implicit Euler: velocity first, then position with the new
    /// velocity, which is stable for steering forces):
    ///
    /// 1. `a = limit(steering, max_force)` (a non-finite steering counts as 0),
    /// 2. `v ← v + a·dt`, then its length is kept within
    ///    [min_speed, max_speed] (a fish never stops: a slow fish keeps its
    ///    direction and swims at min_speed),
    /// 3. `p ← p + v·dt`.
    pub fn integrate(&mut self, steering_m_per_s2: Vec3, params: &SteeringParams, dt_secs: f32) {
        let accel_m_per_s2 = limit(steering_m_per_s2, params.max_force_m_per_s2);
        let heading_before = self.heading();
        let velocity = self.velocity_m_per_s + accel_m_per_s2 * dt_secs;
        // `max` then `min` rather than `clamp`: no panic if a slider sets
        // min > max, and a NaN parameter is ignored.
        let speed_m_per_s = velocity
            .length()
            .max(params.min_speed_m_per_s)
            .min(params.max_speed_m_per_s);
        self.velocity_m_per_s = velocity.normalize_or(heading_before) * speed_m_per_s;
        self.position_m += self.velocity_m_per_s * dt_secs;
    }
}

/// Unit vector along `velocity_m_per_s`, or +x when it is (almost) zero or
/// not finite: the heading of an animal swimming with that velocity.
pub fn heading_of(velocity_m_per_s: Vec3) -> Vec3 {
    if velocity_m_per_s.length() > STILL_SPEED_M_PER_S {
        velocity_m_per_s.normalize_or(Vec3::X)
    } else {
        Vec3::X
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::common::fish::*;

    #[test]
    fn heading_follows_velocity_and_falls_back_to_plus_x_when_still() {
        let moving = Fish::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -0.5), 0.3, 0.0);
        assert_eq!(moving.heading(), Vec3::NEG_Z);
        assert_eq!(moving.speed_m_per_s(), 0.5);
        let still = Fish::new(Vec3::ZERO, Vec3::ZERO, 0.3, 0.0);
        assert_eq!(still.heading(), Vec3::X);
        let broken = Fish::new(Vec3::ZERO, Vec3::NAN, 0.3, 0.0);
        assert!(broken.heading().is_finite());
    }

    #[test]
    fn faster_fish_beat_their_tails_faster() {
        let slow = Fish::new(Vec3::ZERO, Vec3::X * 0.1, 0.3, 0.0);
        let fast = Fish::new(Vec3::ZERO, Vec3::X * 0.8, 0.3, 0.0);
        assert!(fast.tail_beat_hz() > 2.0 * slow.tail_beat_hz());
        let mut fish = fast;
        fish.advance_tail_phase(0.01);
        assert!(fish.tail_phase_rad > 0.0 && fish.tail_phase_rad < TAU);
    }

    #[test]
    fn integrate_respects_max_force_and_speed_limits() {
        let params = SteeringParams::default();
        let mut fish = Fish::new(Vec3::ZERO, Vec3::X * 0.5, 0.3, 0.0);
        // A huge sideways push only changes the velocity by max_force·dt.
        fish.integrate(Vec3::Z * 1000.0, &params, 0.1);
        assert!(fish.velocity_m_per_s.z <= params.max_force_m_per_s2 * 0.1 + 1e-6);
        // Pushing forward forever never exceeds max speed.
        for _ in 0..100 {
            fish.integrate(fish.heading() * 1000.0, &params, 0.1);
        }
        assert!(fish.speed_m_per_s() <= params.max_speed_m_per_s + 1e-5);
        // Braking forever never stops the fish, nor turns it around.
        let heading = fish.heading();
        for _ in 0..100 {
            fish.integrate(-fish.heading() * 1000.0, &params, 0.1);
        }
        assert!(fish.speed_m_per_s() >= params.min_speed_m_per_s - 1e-5);
        assert!(fish.heading().dot(heading) > 0.99);
        // NaN steering is ignored.
        fish.integrate(Vec3::NAN, &params, 0.1);
        assert!(fish.position_m.is_finite() && fish.velocity_m_per_s.is_finite());
    }
}
