//! The objective of low-level learning, Tu & Terzopoulos 1994 §4.2 eq. (2)–(3):
//!
//! E(u) = ∫_{t₀}^{t₁} μ₁ E_u(u(t)) dt + μ₂ E_v(v),  E_u = ½ (ν₁ ‖du/dt‖² + ν₂ ‖d²u/dt²‖²).
//!
//! "To compute v(t) and hence E, we must perform a forward simulation of the
//! dynamic model over a time interval t₀ ≤ t ≤ t₁ with the actuation function
//! inputs u(t)": [`evaluate`] builds a [`FishBody`] of the chosen species at rest
//! (centre of mass at the origin, heading +x, body frame z up), drives it with the
//! spline for the interval and measures the trajectory. The derivatives of u are
//! finite differences of u at the body's steps (Δt = 0.055 s).
//!
//! E_v is a terminal or averaged criterion, in body lengths so that fish and
//! sharks share the weights ([`Task`]):
//!
//! | task | E_v |
//! |------|-----|
//! | reach a target (the paper's usual choice) | final distance of the centre of mass from the target, body lengths |
//! | hold a speed ("closeness to a specified speed") | \|v̄ − v*\| · T/2: the distance the error in mean forward speed over the second half of the interval costs, body lengths |
//! | turn at a rate | the final heading error (radians) + the speed term above |
//!
//! The second half only: the fish starts at rest and needs about a second to reach
//! its speed. A radian of heading error counts like a body length of distance.

use crate::sim::common::fmath;
use glam::Vec3;
use serde::{Deserialize, Serialize};
use std::f32::consts::{PI, TAU};

use crate::sim::body::physical_fish::BodySpecies;
use crate::sim::body::{BodyParams, FishBody, MUSCLE_COUNT, PectoralFins};
use crate::sim::learning::muscle_spline::{DEFAULT_SAMPLE_COUNT, Interpolation, MuscleSpline};

/// Penalty reported instead of a non-finite objective (the body guards against
/// NaN, so this is never expected), dimensionless.
pub const NON_FINITE_PENALTY: f32 = 1.0e6;

/// What the fish practises: the trajectory criterion E_v.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Task {
    /// Be as close as possible to a target at the end of the interval. Target in
    /// body lengths from the start position: `forward` along the starting heading,
    /// `left` to its left.
    ReachTarget {
        forward_body_lengths: f32,
        left_body_lengths: f32,
    },
    /// Swim straight ahead at a given mean speed, body lengths per second.
    HoldSpeed { speed_body_lengths_per_sec: f32 },
    /// Turn at a rate (degrees per second, + = left) while swimming at a speed
    /// (body lengths per second).
    TurnHeading {
        turn_rate_deg_per_sec: f32,
        speed_body_lengths_per_sec: f32,
    },
}

impl Task {
    /// The default drill: a target 4 body lengths straight ahead, farther than
    /// any fish gets in the default interval (about 1.2 body lengths), so the
    /// criterion keeps rewarding distance: "swim as far as you can".
    pub const SWIM_FAR: Self = Self::ReachTarget {
        forward_body_lengths: 4.0,
        left_body_lengths: 0.0,
    };

    /// The drill in words ("swim as far as it can", "turn left at 15°/s").
    pub fn label(&self) -> String {
        match *self {
            Self::ReachTarget { .. } => "swim as far as it can".to_owned(),
            Self::HoldSpeed {
                speed_body_lengths_per_sec,
            } => format!("swim straight at {speed_body_lengths_per_sec} body lengths/s"),
            Self::TurnHeading {
                turn_rate_deg_per_sec,
                ..
            } => format!(
                "turn {} at {}°/s",
                if turn_rate_deg_per_sec >= 0.0 {
                    "left"
                } else {
                    "right"
                },
                turn_rate_deg_per_sec.abs()
            ),
        }
    }
}

/// The weights of eq. (2) and (3).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ObjectiveWeights {
    /// μ₁, weight of the smoothness integral, body lengths per (unit of ∫E_u dt).
    /// Default 5e-4, tuned: a full-amplitude 2 Hz swimming wave in the middle and
    /// posterior segments has ∫E_u dt ≈ 600 over 2.5 s, i.e. costs 0.3 body
    /// lengths. Measured (2000 steps, seed 1, abstracted with M = 2): μ₁ = 1e-4
    /// learns jagged controls (85 % of their energy in two modes, abstracted swim
    /// 0.28 body lengths/s), 5e-4 smoother ones (90 %, 0.33), 1e-3 and 2e-3 beat
    /// slower (1.35 and 0.8 Hz; 0.21 and 0.10 body lengths/s).
    pub mu1_smoothness: f32,
    /// μ₂, weight of the trajectory criterion, dimensionless. Default 1.
    pub mu2_trajectory: f32,
    /// ν₁, weight of ‖du/dt‖² (s², dimensionless in effect). Default 1, chosen.
    pub nu1_velocity: f32,
    /// ν₂, weight of ‖d²u/dt²‖², s². Default 0.01, chosen: with it the two terms
    /// of a 2 Hz wave are of the same order ((2π · 2 Hz)² ≈ 160 against 1/ν₂ = 100).
    /// Measured: ν₂ = 0.05 (with μ₁ = 5e-4) slows the learned beat to 1.45 Hz and
    /// the swim to 0.19 body lengths/s.
    pub nu2_acceleration: f32,
}

impl Default for ObjectiveWeights {
    fn default() -> Self {
        Self {
            mu1_smoothness: 5.0e-4,
            mu2_trajectory: 1.0,
            nu1_velocity: 1.0,
            nu2_acceleration: 0.01,
        }
    }
}

/// One learning problem: who learns what over which interval.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct TrainingSetup {
    pub species: BodySpecies,
    pub task: Task,
    /// Training interval t₁ − t₀, seconds. Default 2.5, chosen: with N = 15 samples
    /// (0.18 s apart) the splines can make waves up to about 1.5 Hz, where this
    /// body swims at half its hand-tuned top speed (`body/motor_controller.rs`:
    /// 0.31 body lengths/s at 1.5 Hz, 0.60 at 3 Hz); a 10 s interval with 15
    /// samples could beat at most 0.7 Hz (0.1 body lengths/s).
    pub interval_secs: f32,
    /// N, samples per muscle. Default 15 (paper).
    pub sample_count: usize,
    pub interpolation: Interpolation,
    pub weights: ObjectiveWeights,
    /// The body. Default: the app's `BodyParams::default()` (tests may use a
    /// cheaper `jacobian_interval = 2`).
    pub body: BodyParams,
}

impl Default for TrainingSetup {
    fn default() -> Self {
        Self {
            species: BodySpecies::Fish,
            task: Task::SWIM_FAR,
            interval_secs: 2.5,
            sample_count: DEFAULT_SAMPLE_COUNT,
            interpolation: Interpolation::Cubic,
            weights: ObjectiveWeights::default(),
            body: BodyParams::default(),
        }
    }
}

impl TrainingSetup {
    /// The simulated interval, a whole number of body steps, seconds (the
    /// requested interval rounded to steps).
    pub fn simulated_secs(&self) -> f32 {
        self.steps() as f32 * self.body.dt_secs
    }

    /// Body steps in one evaluation (at least 1).
    pub fn steps(&self) -> usize {
        let dt = self.body.dt_secs;
        if dt.is_finite() && dt > 0.0 && self.interval_secs.is_finite() {
            ((self.interval_secs / dt).round() as usize).clamp(1, 100_000)
        } else {
            1
        }
    }
}

/// Where the fish was at one step of an evaluation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PathPoint {
    pub time_secs: f32,
    /// Centre of mass, metres, body frame of the start (x the starting heading,
    /// y left, z up; origin the starting position).
    pub position_m: Vec3,
    /// Horizontal heading of the fore body, degrees from the start (+ = left,
    /// unwrapped).
    pub heading_deg: f32,
}

/// The result of one forward simulation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Evaluation {
    /// E = smoothness + trajectory (finite).
    pub objective: f32,
    /// μ₁ ∫ E_u dt.
    pub smoothness: f32,
    /// μ₂ E_v.
    pub trajectory: f32,
    /// Final displacement along the starting heading, body lengths.
    pub forward_body_lengths: f32,
    /// Mean forward speed over the second half of the interval, body lengths/s.
    pub speed_body_lengths_per_sec: f32,
    /// Heading change (the last third's mean, at most 1 s), degrees, + = left.
    pub heading_change_deg: f32,
    /// The trajectory, one point per body step (the first at rest, t = 0).
    pub path: Vec<PathPoint>,
}

fn finite_or(x: f32, fallback: f32) -> f32 {
    if x.is_finite() { x } else { fallback }
}

/// Horizontal heading of a body's fore body, radians.
pub(crate) fn heading_rad(body: &FishBody) -> f32 {
    let f = body.forward();
    fmath::atan2(f.y, f.x)
}

/// Adds the wrapped change from `previous` to `now` to `unwrapped`.
pub(crate) fn unwrap_angle(unwrapped: f32, previous: f32, now: f32) -> f32 {
    unwrapped + (now - previous + PI).rem_euclid(TAU) - PI
}

/// Forward simulation of `controls` under `setup` and its objective. The spline's
/// own duration is stretched to the setup's interval. Deterministic; never NaN.
pub fn evaluate(setup: &TrainingSetup, controls: &MuscleSpline) -> Evaluation {
    let length_m = setup.species.body_length_m();
    let mut body = FishBody::with_params(length_m, Vec3::ZERO, Vec3::X, setup.body);
    let start = body.centre_of_mass_m();
    let dt = body.dt_secs();
    let steps = setup.steps();
    let interval = steps as f32 * dt;
    let time_scale = controls.duration_secs() / interval;
    let w = setup.weights;

    let mut path = Vec::with_capacity(steps + 1);
    path.push(PathPoint {
        time_secs: 0.0,
        position_m: Vec3::ZERO,
        heading_deg: 0.0,
    });
    let mut previous_heading = heading_rad(&body);
    let start_heading = previous_heading;
    let mut unwrapped = start_heading;
    let mut u_prev: [f32; MUSCLE_COUNT] = controls.value_at(0.0);
    let mut du_prev: Option<[f32; MUSCLE_COUNT]> = None;
    let mut smoothness_integral = 0.0f32;
    for k in 1..=steps {
        let t = k as f32 * dt;
        let u = controls.value_at(t * time_scale);
        let step_start_secs = t - dt;
        body.step_with(&PectoralFins::NEUTRAL, Vec3::ZERO, |s| {
            controls.value_at((step_start_secs + s) * time_scale)
        });
        let mut du = [0.0; MUSCLE_COUNT];
        let (mut v2, mut a2) = (0.0, 0.0);
        for m in 0..MUSCLE_COUNT {
            du[m] = (u[m] - u_prev[m]) / dt;
            v2 += du[m] * du[m];
            if let Some(p) = du_prev {
                let d2 = (du[m] - p[m]) / dt;
                a2 += d2 * d2;
            }
        }
        smoothness_integral += 0.5 * (w.nu1_velocity * v2 + w.nu2_acceleration * a2) * dt;
        u_prev = u;
        du_prev = Some(du);
        let h = heading_rad(&body);
        unwrapped = unwrap_angle(unwrapped, previous_heading, h);
        previous_heading = h;
        path.push(PathPoint {
            time_secs: t,
            position_m: body.centre_of_mass_m() - start,
            heading_deg: (unwrapped - start_heading).to_degrees(),
        });
    }
    let last = path.last().map_or(Vec3::ZERO, |p| p.position_m);
    let forward_bl = last.x / length_m;
    let half = steps / 2;
    let half_secs = (steps - half) as f32 * dt;
    let speed = (last.x - path[half].position_m.x) / length_m / half_secs;
    let window = ((1.0f32.min(interval / 3.0) / dt).round() as usize).clamp(1, steps);
    let heading_change_deg = path[steps + 1 - window..]
        .iter()
        .map(|p| p.heading_deg)
        .sum::<f32>()
        / window as f32;

    let speed_error_bl = |target: f32| (speed - target).abs() * half_secs;
    let e_v = match setup.task {
        Task::ReachTarget {
            forward_body_lengths,
            left_body_lengths,
        } => {
            let target = glam::Vec2::new(forward_body_lengths, left_body_lengths);
            let end = glam::Vec2::new(last.x, last.y) / length_m;
            end.distance(target)
        }
        Task::HoldSpeed {
            speed_body_lengths_per_sec,
        } => speed_error_bl(speed_body_lengths_per_sec),
        Task::TurnHeading {
            turn_rate_deg_per_sec,
            speed_body_lengths_per_sec,
        } => {
            let target_deg = turn_rate_deg_per_sec * interval;
            (heading_change_deg - target_deg).abs().to_radians()
                + speed_error_bl(speed_body_lengths_per_sec)
        }
    };
    let smoothness = finite_or(w.mu1_smoothness * smoothness_integral, NON_FINITE_PENALTY);
    let trajectory = finite_or(w.mu2_trajectory * e_v, NON_FINITE_PENALTY);
    Evaluation {
        objective: finite_or(smoothness + trajectory, NON_FINITE_PENALTY),
        smoothness,
        trajectory,
        forward_body_lengths: finite_or(forward_bl, 0.0),
        speed_body_lengths_per_sec: finite_or(speed, 0.0),
        heading_change_deg: finite_or(heading_change_deg, 0.0),
        path,
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::learning::objective::*;

    fn cheap() -> TrainingSetup {
        TrainingSetup {
            interval_secs: 1.0,
            body: BodyParams {
                jacobian_interval: 2,
                ..BodyParams::default()
            },
            ..TrainingSetup::default()
        }
    }

    #[test]
    fn a_resting_fish_stays_put_and_pays_the_whole_distance() {
        let setup = cheap();
        let rest = MuscleSpline::constant(15, 1.0, Interpolation::Cubic, 0.0);
        let e = evaluate(&setup, &rest);
        assert!(e.forward_body_lengths.abs() < 1e-3);
        assert!((e.trajectory - 4.0).abs() < 1e-3, "{e:?}");
        assert_eq!(e.smoothness, 0.0);
        assert_eq!(e.path.len(), setup.steps() + 1);
    }

    #[test]
    fn evaluation_is_deterministic_and_finite_for_wild_controls() {
        let setup = cheap();
        let mut zigzag = MuscleSpline::constant(15, 1.0, Interpolation::Cubic, 0.0);
        for i in 0..15 {
            for m in 0..MUSCLE_COUNT {
                zigzag.set_sample(i, m, ((i + m) % 2) as f32);
            }
        }
        let a = evaluate(&setup, &zigzag);
        let b = evaluate(&setup, &zigzag);
        assert_eq!(a, b);
        assert!(a.objective.is_finite() && a.smoothness > 0.0);
        assert!(a.path.iter().all(|p| p.position_m.is_finite()));
    }
}
