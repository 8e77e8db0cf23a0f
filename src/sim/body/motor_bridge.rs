//! The bridge from the steering layer of the physics scene to the muscles: a
//! *desired velocity* (what the boid forces of `boids/forces.rs` and `common/steering.rs`
//! ask of a point-mass fish) becomes motor commands of Tu & Terzopoulos 1994
//! §3.3–3.4: a swim-MC speed, a steering bend of the turning segments and
//! pectoral fin angles. (The reef's minds do not use it: their behaviour
//! routines pick the motor controllers themselves, `reef/motor_choice.rs`.)
//!
//! | desired velocity d, fish heading f           | command |
//! |----------------------------------------------|---------|
//! | ‖d‖                                          | swim-MC speed fraction ‖d‖ / top speed |
//! | horizontal angle Δ from f to d              | steering command clamp(Δ × [`MotorParams::steer_gain_per_rad`], −1, 1), + = left (`body::turn_mc::add_steering`); none while a hand turn-MC turn runs |
//! | elevation of d minus the fish's pitch        | both fins pitched by 2 × the difference, at most ±0.5 rad (ascend, descend) |
//! | ‖d‖ below half the current speed            | both fins across the flow (brake), no swimming |
//!
//! Why a continuous steering command and not turn-MC turns: a turn-MC turn
//! contracts quickly and restores twenty times slower, so a 90° turn takes 7.5 s
//! (`body/turn_mc.rs`), and one restarted every step never finishes its quick
//! stroke. The steering command holds the turning side's bend for as long as the
//! heading error lasts, proportionally to it, and the tail's thrust on the bent
//! body yaws the fish at up to about 30–41°/s (measured by the census scripts
//! `turn-agility` and `closed-loop-turn-times`). The discrete turn-MC stays for
//! hand commands (`PhysicalFish::turn`).
//!
//! Frames: the steering layer lives in the tank frame (y up); the body in its own
//! frame (z up, `body/fish_body.rs`). [`to_body_frame`] and [`to_tank_frame`]
//! convert between them (a rotation of 90° about x).

use crate::sim::common::fmath;
use std::f32::consts::PI;

use glam::Vec3;
use serde::{Deserialize, Serialize};

use crate::sim::body::PectoralFins;

/// Swimming speed of the default body at the swim-MC's top setting, body lengths
/// per second. 0.6, measured (census `speed-table`: 0.585 at 2.3 Hz and full
/// amplitude on the converged body with the braced tail fin; test `the_default_body_is_converged`
/// checks it within 3 %).
pub const TOP_SPEED_BODY_LENGTHS_PER_SEC: f32 = 0.6;

/// The tuning of the body's controllers between the steering layer and the
/// muscles: the motor bridge's gains ([`MotorBridge::plan`]), the held steering
/// bend of the turn-MC's segments (`body::turn_mc::add_steering`) and the swim
/// setting of a running turn (`PhysicalFish::step`). Held by the bridge of every
/// [`PhysicalFish`](crate::sim::body::physical_fish::PhysicalFish) (the
/// `Default`), read through `MotorBridge::params` and `PhysicalFish::motor_params`.
///
/// Left as consts: [`TOP_SPEED_BODY_LENGTHS_PER_SEC`] (a measured property of the
/// body, read by the reef's planning and demos), the turn-MC's key table and its
/// quick rate and beat phase (`body/turn_mc.rs`, used in `const` key tables), the
/// key-turn measurement's lead-in, settle and averaging times (a measurement
/// protocol, not tuning), the paper's largest single turn (paper data) and the
/// heading window (`physical_fish::HEADING_WINDOW_STEPS`, an array length).
#[derive(Clone, Debug, PartialEq)]
pub struct MotorParams {
    /// Steering command per radian of heading error, 1/rad. 4, tuned
    /// (census `closed-loop-turn-times`): full steering from 14° of
    /// error. On the converged body with the braced tail fin and the averaged heading,
    /// a 90° turn from 0.7 of the top speed reaches 81° in 3.4–3.5 s at gain 4, 3.4–3.6 s
    /// at 3; 30° turns from 0.7 take 1.6–1.7 s at 4, 2.0–2.1 s at 3; gains 5 and 6 gain
    /// under 0.1 s on 90° turns. (Before the brace, gain 3: 3.0 s; on the earlier,
    /// unconverged body 3.1 s, and 3.5 s at gain 1.5.)
    pub steer_gain_per_rad: f32,
    /// Fin pitch per radian of elevation error (2, chosen: a 15° climb request tilts
    /// the fins by the full 0.5 rad).
    pub pitch_gain: f32,
    /// Largest fin pitch, radians (0.5, as in the fin tests of `body/tests/fins.rs`).
    pub max_fin_pitch_rad: f32,
    /// Smallest swim-MC speed while a turn runs, fraction of the top speed (0.5,
    /// chosen): the turn comes from the tail's thrust on the bent body
    /// (`body/turn_mc.rs`), so a turn without swimming barely turns.
    pub min_turn_speed_fraction: f32,
    /// swim-MC speed while a turn-MC turn runs, fraction of the top speed: 1, the
    /// setting at which the turn-MC's key turns are measured
    /// (`body::turn_mc::measure_heading_change_deg` swims at `SwimParams::MAX`). A
    /// turn is made by the tail's thrust on the bent body, so at half the thrust
    /// the 90° key turned the fish 43° (at full thrust 88°, measured in the
    /// browser): whatever speed the fish swam at, its tail beats at this setting
    /// until the turn is done, and its key turns keep their angles
    /// (test `key_turns_hold_at_every_swim_speed`).
    pub turn_swim_speed_fraction: f32,
    /// Contraction added to the turning side of the anterior segment at full steering
    /// (|steer| = 1), contraction factor. 0.5, measured on the default body with
    /// census `closed-loop-turn-times` (closed-loop turns of ±90° and
    /// ±30° through the bridge from 1.0, 0.7, 0.4 and 0.2 of the top speed, three
    /// tail-beat phases at the start; seconds to 90 % of the turn, 15 s limit), anterior
    /// / middle / posterior biases:
    ///
    /// | biases | worst time | never | shortest spine |
    /// |---|---:|---:|---:|
    /// | **0.5 / 0.5 / 0.25** | **5.9 s** | 0 | **0.87** |
    /// | 0.5 / 0.5 / 0.5 | 4.8 s | 0 | 0.86 |
    /// | 0.6 / 0.6 / 0.3 | 6.3 s | 0 | 0.85 |
    /// | 0.6 / 0.6 / 0.45 | 5.2 s | 0 | 0.85 |
    /// | 0.75 / 0.75 / 0.375 | 5.5 s | 0 | 0.83 |
    ///
    /// Kept at 0.5 / 0.5 / 0.25 because it folds the body least: the stronger bends
    /// turn tighter circles (0.75 / 0.75 / 0.375: a 90° turn from 0.7 of the top speed
    /// in a radius under 1 body length, against 1.09 here) but fold schooling fish
    /// below 0.85 of their length (`physics_world` test). With the earlier spring
    /// damping of 0.1 (`fish_body.rs`, `BodyParams::spring_damping`) every set had
    /// turns that never finished: a slow fish with a held bend fell into a second,
    /// almost motionless state (0.02 m/s). The bend is held as long as the command
    /// lasts, so the tail's thrust on the bent body keeps yawing the fish (see the
    /// module doc of `body/turn_mc.rs`).
    pub steer_anterior_bias: f32,
    /// The same for the middle segment, whose swim wave beats around the bent mean.
    /// 0.5, measured with [`MotorParams::steer_anterior_bias`] (`body/turn_mc.rs`).
    pub steer_middle_bias: f32,
    /// The same for the posterior segment. 0.25, measured with
    /// [`MotorParams::steer_anterior_bias`].
    pub steer_posterior_bias: f32,
}

impl MotorParams {
    /// The steering bends (anterior, middle, posterior).
    pub fn steer_biases(&self) -> [f32; 3] {
        [
            self.steer_anterior_bias,
            self.steer_middle_bias,
            self.steer_posterior_bias,
        ]
    }
}

impl Default for MotorParams {
    fn default() -> Self {
        Self {
            steer_gain_per_rad: 4.0,
            pitch_gain: 2.0,
            max_fin_pitch_rad: 0.5,
            min_turn_speed_fraction: 0.5,
            turn_swim_speed_fraction: 1.0,
            steer_anterior_bias: 0.5,
            steer_middle_bias: 0.5,
            steer_posterior_bias: 0.25,
        }
    }
}

/// Tank frame (y up) → body frame (z up).
pub fn to_body_frame(v: Vec3) -> Vec3 {
    Vec3::new(v.x, -v.z, v.y)
}

/// Body frame (z up) → tank frame (y up).
pub fn to_tank_frame(v: Vec3) -> Vec3 {
    Vec3::new(v.x, v.z, -v.y)
}

/// The level (horizontal) angle from heading `from` to heading `to` in the tank
/// frame, degrees, + = to the fish's left (left of h is y × h); 0 for a vertical or
/// zero vector.
pub fn level_turn_deg(from: Vec3, to: Vec3) -> f32 {
    let level = |v: Vec3| Vec3::new(v.x, 0.0, v.z).normalize_or_zero();
    let (a, b) = (level(from), level(to));
    fmath::atan2(Vec3::Y.cross(a).dot(b), a.dot(b)).to_degrees()
}

/// What the bridge asks of the motor controllers this step.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct MotorIntent {
    /// swim-MC speed, fraction of the top speed in [0, 1].
    pub speed_fraction: f32,
    /// A new turn to start, degrees (+ = left); `None` keeps the current one.
    pub start_turn_deg: Option<f32>,
    /// Continuous steering in [−1, 1], + = left (`body::turn_mc::add_steering`).
    pub steer: f32,
    /// Pectoral fin angles.
    pub fins: PectoralFins,
}

/// The bridge (stateless but for its tuning: the steering command follows the
/// heading error).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MotorBridge {
    params: MotorParams,
}

/// Angle wrapped to (−π, π].
fn wrap(a: f32) -> f32 {
    let w = (a + PI).rem_euclid(2.0 * PI) - PI;
    if w <= -PI { w + 2.0 * PI } else { w }
}

impl MotorBridge {
    /// A bridge with the tuning `params`.
    pub fn new(params: MotorParams) -> Self {
        Self { params }
    }

    /// The bridge's tuning.
    pub fn params(&self) -> &MotorParams {
        &self.params
    }

    /// Plans this step's motor commands for a fish with unit `forward` (tank
    /// frame), moving at `speed_m_per_s`, whose top swimming speed is
    /// `top_speed_m_per_s`, that wants `desired_m_per_s` (tank frame). `turning`
    /// says whether its turn-MC is still busy. Non-finite input asks for nothing.
    pub fn plan(
        &mut self,
        desired_m_per_s: Vec3,
        forward: Vec3,
        speed_m_per_s: f32,
        top_speed_m_per_s: f32,
        turning: bool,
    ) -> MotorIntent {
        let idle = MotorIntent {
            speed_fraction: 0.0,
            start_turn_deg: None,
            steer: 0.0,
            fins: PectoralFins::NEUTRAL,
        };
        if !(desired_m_per_s.is_finite() && forward.is_finite() && top_speed_m_per_s > 0.0) {
            return idle;
        }
        let d = to_body_frame(desired_m_per_s);
        let f = to_body_frame(forward);
        let desired_speed = d.length();
        let speed = if speed_m_per_s.is_finite() {
            speed_m_per_s.max(0.0)
        } else {
            0.0
        };
        if desired_speed < 0.5 * speed && speed > 0.3 * top_speed_m_per_s {
            return MotorIntent {
                fins: PectoralFins::BRAKE,
                ..idle
            };
        }
        let mut speed_fraction = (desired_speed / top_speed_m_per_s).clamp(0.0, 1.0);

        // Yaw: steer towards the desired horizontal heading, unless a hand turn runs.
        let horizontal = d.truncate();
        let mut steer = 0.0;
        if !turning
            && horizontal.length() > 1e-3 * top_speed_m_per_s
            && f.truncate().length() > 1e-3
        {
            let goal = fmath::atan2(horizontal.y, horizontal.x);
            let heading = fmath::atan2(f.y, f.x);
            steer = (self.params.steer_gain_per_rad * wrap(goal - heading)).clamp(-1.0, 1.0);
        }
        // A turn comes from the tail's thrust on the bent body: swim. Steering
        // turns a circle of about 0.6 body lengths whatever the speed, so the
        // heading rate grows with the speed and a sharp turn swims at full beat.
        speed_fraction = if turning {
            speed_fraction.max(self.params.min_turn_speed_fraction)
        } else {
            speed_fraction.max(steer.abs())
        };

        // Pitch: climb or dive with the fins.
        let elevation = fmath::atan2(d.z, horizontal.length());
        let pitch = fmath::asin(f.z.clamp(-1.0, 1.0));
        let max_pitch = self.params.max_fin_pitch_rad;
        let fin_pitch = (self.params.pitch_gain * (elevation - pitch)).clamp(-max_pitch, max_pitch);
        MotorIntent {
            speed_fraction,
            start_turn_deg: None,
            steer,
            fins: if desired_speed > 0.0 {
                PectoralFins::pitch(fin_pitch)
            } else {
                PectoralFins::NEUTRAL
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::body::motor_bridge::*;

    #[test]
    fn frames_convert_back_and_forth_and_up_is_up() {
        let v = Vec3::new(1.0, 2.0, 3.0);
        assert_eq!(to_tank_frame(to_body_frame(v)), v);
        assert_eq!(to_body_frame(Vec3::Y), Vec3::Z);
        // A right-handed rotation: x × y = z in both frames.
        assert_eq!(
            to_body_frame(Vec3::X).cross(to_body_frame(Vec3::Y)),
            to_body_frame(Vec3::Z)
        );
        // Left of +x (y up) is −z, and the body frame agrees: +y_body.
        assert!((level_turn_deg(Vec3::X, Vec3::NEG_Z) - 90.0).abs() < 1e-4);
        assert_eq!(to_tank_frame(Vec3::Y), Vec3::NEG_Z);
    }

    #[test]
    fn desired_velocity_maps_to_speed_turn_and_fins() {
        let mut bridge = MotorBridge::default();
        // Straight ahead at half the top speed: no turn, level fins.
        let ahead = bridge.plan(Vec3::X * 0.1, Vec3::X, 0.1, 0.2, false);
        assert!((ahead.speed_fraction - 0.5).abs() < 1e-5);
        assert_eq!(ahead.start_turn_deg, None);
        assert_eq!(ahead.steer, 0.0);
        assert!((ahead.fins.left_angle_rad - std::f32::consts::FRAC_PI_2).abs() < 1e-5);
        // 60° to the left in the tank frame (y up, so left of +x is −z): full left.
        let left = Vec3::new(0.5, 0.0, -(3f32.sqrt()) / 2.0) * 0.2;
        assert_eq!(bridge.plan(left, Vec3::X, 0.1, 0.2, false).steer, 1.0);
        // 10° to the right: proportional right steering.
        let right10 = Vec3::new(
            fmath::cos(10f32.to_radians()),
            0.0,
            fmath::sin(10f32.to_radians()),
        );
        let steer = bridge.plan(right10, Vec3::X, 0.1, 0.2, false).steer;
        assert!(
            (steer + MotorParams::default().steer_gain_per_rad * 10f32.to_radians()).abs() < 1e-4,
            "{steer}"
        );
        // A running hand turn is not fought.
        assert_eq!(bridge.plan(left, Vec3::X, 0.1, 0.2, true).steer, 0.0);
        // Up: fins pitched up; down: pitched down.
        let up = bridge.plan(Vec3::new(1.0, 0.5, 0.0), Vec3::X, 0.1, 0.2, false);
        assert!(up.fins.left_angle_rad > std::f32::consts::FRAC_PI_2);
        let down = bridge.plan(Vec3::new(1.0, -0.5, 0.0), Vec3::X, 0.1, 0.2, false);
        assert!(down.fins.left_angle_rad < std::f32::consts::FRAC_PI_2);
        // Stop while fast: brake.
        let stop = bridge.plan(Vec3::ZERO, Vec3::X, 0.2, 0.2, false);
        assert_eq!(stop.fins, PectoralFins::BRAKE);
        assert_eq!(stop.speed_fraction, 0.0);
        // Garbage in, nothing out.
        let nan = bridge.plan(Vec3::NAN, Vec3::X, 0.1, 0.2, false);
        assert_eq!(nan.speed_fraction, 0.0);
    }
}
