//! The learned speed and steering map, Tu & Terzopoulos 1994 §4.3: "After it has
//! abstracted controllers for these tasks, the artificial fish can construct a
//! forward speed and steering map by interpolating across amplitudes,
//! frequencies, and phases of the sinusoidal basis functions in the set of
//! abstracted controllers."
//!
//! Each trained drill gives an [`AbstractedController`]; [`measure_motion`] runs it
//! on and on from rest and measures the speed and turn rate it actually produces
//! ([`MotionMeasurement`]); those measurements, not the drills' targets, place it
//! in the map. Drills that swim straight (reach a target ahead, hold a speed) form
//! the speed axis, turn drills the steering axis, left and right separately (a
//! missing side is the mirror image of the other).
//!
//! [`LearnedMotorMap::controller_for`]`(speed_fraction, turn_fraction)`:
//! 1. speed: the straight controllers sorted by measured speed, with a resting
//!    controller (all muscles relaxed) at speed 0; the request `speed_fraction` ×
//!    the fastest learned speed is interpolated between its two neighbours;
//! 2. turn: the turn controllers of the requested side sorted by measured rate, with
//!    the straight controller of step 1 at rate 0; `|turn_fraction|` × the largest
//!    learned rate is interpolated likewise.
//!
//! Interpolating two controllers: means and amplitudes linearly, frequencies
//! linearly, phases along the shorter arc; mode j with mode j, the modes of each
//! controller ordered by frequency (a turn's slow bend meets a swim's slow mode,
//! the beats meet each other). Before that each mode is shifted in time so that its reference phasor
//! Σ_m A_m e^{iφ_m} (right-side muscles counted with the opposite sign, as they beat
//! in antiphase) has phase 0: only the phases between muscles carry meaning, and two
//! drills started their waves at different moments.
//!
//! [`LearnedMotor`] runs the map like the hand-tuned swim-MC and turn-MC: each step
//! it advances one oscillator phase per mode by 2π f Δt (continuous when the
//! frequency changes) and returns the 12 contractions
//! u_m = ū_m + Σⱼ A_mj cos(θⱼ + φ_mj), clamped to [0, 1].

use crate::sim::common::fmath;
use glam::Vec3;
use serde::{Deserialize, Serialize};
use std::f32::consts::{PI, TAU};

use crate::sim::body::physical_fish::BodySpecies;
use crate::sim::body::turn_mc::mirror_muscles;
use crate::sim::body::{
    BodyParams, FishBody, MUSCLE_COUNT, MuscleSegment, PectoralFins, Side, SwimMc,
    body_layout::muscle_index,
};
use crate::sim::learning::abstraction::{AbstractedController, FourierMode};
use crate::sim::learning::objective::{Task, heading_rad, unwrap_angle};

/// Most modes a learned motor runs (oscillators), count.
pub const MAX_MODES: usize = 4;
/// How long [`measure_motion`] runs a controller by default, seconds. 8, chosen:
/// the first half (speeding up from rest) is discarded, the second half measured.
pub const MEASURE_SECS: f32 = 8.0;

/// What a controller does when run on and on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct MotionMeasurement {
    /// Path speed of the centre of mass, body lengths per second.
    pub speed_body_lengths_per_sec: f32,
    /// Heading change per second, degrees (+ = left).
    pub turn_rate_deg_per_sec: f32,
}

/// Runs `controller` periodically on a body of `species` from rest for `secs` and
/// measures the second half: speed from the centre of mass sampled every 0.5 s
/// (the path without the tail beat's wiggle), turn rate from the fore body's
/// heading averaged over the first and last second of that half. Deterministic.
pub fn measure_motion(
    controller: &AbstractedController,
    species: BodySpecies,
    params: BodyParams,
    secs: f32,
) -> MotionMeasurement {
    measure_motion_with(species, params, secs, |t| controller.value_at(t))
}

/// The hand-tuned swim-MC at `speed_fraction`, measured like [`measure_motion`]
/// (the yardstick of the learned controllers).
pub fn measure_hand_tuned_swim(
    speed_fraction: f32,
    species: BodySpecies,
    params: BodyParams,
    secs: f32,
) -> MotionMeasurement {
    let swim = SwimMc::default();
    let swim_params = swim.params_for_speed(speed_fraction);
    measure_motion_with(species, params, secs, move |t| {
        swim.muscles_at(&swim_params, t)
    })
}

/// [`measure_motion`] for any source of contractions, a function of the time in
/// seconds since the start, sampled at every substep of the body.
pub fn measure_motion_with(
    species: BodySpecies,
    params: BodyParams,
    secs: f32,
    mut muscles_at: impl FnMut(f32) -> [f32; MUSCLE_COUNT],
) -> MotionMeasurement {
    let length_m = species.body_length_m();
    let mut body = FishBody::with_params(length_m, Vec3::ZERO, Vec3::X, params);
    let dt = body.dt_secs();
    let steps = ((secs.max(2.0) / dt).round() as usize).max(4);
    let half = steps / 2;
    let second = ((1.0 / dt).round() as usize).clamp(1, half / 2);
    let every = ((0.5 / dt).round() as usize).max(1);
    let mut previous = heading_rad(&body);
    let mut unwrapped = previous;
    let (mut early, mut late) = (0.0f32, 0.0f32);
    let mut path_m = 0.0f32;
    let mut last_point = body.centre_of_mass_m();
    for k in 1..=steps {
        let start = (k - 1) as f32 * dt;
        body.step_with(&PectoralFins::NEUTRAL, Vec3::ZERO, |t| {
            muscles_at(start + t)
        });
        let h = heading_rad(&body);
        unwrapped = unwrap_angle(unwrapped, previous, h);
        previous = h;
        if k > half && k <= half + second {
            early += unwrapped / second as f32;
        }
        if k > steps - second {
            late += unwrapped / second as f32;
        }
        if k == half {
            last_point = body.centre_of_mass_m();
        }
        if k > half && (k - half).is_multiple_of(every) {
            let p = body.centre_of_mass_m();
            path_m += p.distance(last_point);
            last_point = p;
        }
    }
    let measured_secs = ((steps - half) / every * every) as f32 * dt;
    let between_secs = (steps - half - second) as f32 * dt;
    let speed = path_m / length_m / measured_secs.max(dt);
    let rate = (late - early).to_degrees() / between_secs.max(dt);
    MotionMeasurement {
        speed_body_lengths_per_sec: if speed.is_finite() { speed } else { 0.0 },
        turn_rate_deg_per_sec: if rate.is_finite() { rate } else { 0.0 },
    }
}

/// One trained drill, abstracted and measured.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LearnedController {
    /// The drill it was trained on.
    pub task: Task,
    pub controller: AbstractedController,
    /// What it does (see [`measure_motion`]).
    pub motion: MotionMeasurement,
}

impl LearnedController {
    /// Abstracted controller `controller` for `task`, measured on `species`.
    pub fn measured(
        task: Task,
        controller: AbstractedController,
        species: BodySpecies,
        params: BodyParams,
    ) -> Self {
        let motion = measure_motion(&controller, species, params, MEASURE_SECS);
        Self {
            task,
            controller,
            motion,
        }
    }

    /// Where the drill sits in the map.
    fn role(&self) -> Role {
        match self.task {
            Task::HoldSpeed { .. } => Role::Straight,
            Task::ReachTarget {
                left_body_lengths: 0.0,
                ..
            } => Role::Straight,
            Task::ReachTarget {
                left_body_lengths, ..
            } => side_role(left_body_lengths),
            Task::TurnHeading {
                turn_rate_deg_per_sec,
                ..
            } => side_role(turn_rate_deg_per_sec),
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Role {
    Straight,
    Left,
    Right,
}

fn side_role(x: f32) -> Role {
    if x > 0.0 { Role::Left } else { Role::Right }
}

/// Why a map could not be built.
#[derive(Clone, Debug, PartialEq)]
pub enum LearnedMapError {
    NoStraightController,
    InvalidController,
}

impl std::fmt::Display for LearnedMapError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(crate::i18n::ts(match self {
            Self::NoStraightController => "learning-map-no-straight",
            Self::InvalidController => "learning-map-invalid",
        }))
    }
}

impl std::error::Error for LearnedMapError {}

/// A point of one axis of the map: a controller (phases normalised) and where it
/// sits (speed or |turn rate|).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct MapKey {
    at: f32,
    controller: AbstractedController,
}

/// The learned speed and steering map (see the module doc).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LearnedMotorMap {
    straight: Vec<MapKey>,
    left: Vec<MapKey>,
    right: Vec<MapKey>,
    top_speed_body_lengths_per_sec: f32,
}

/// +1 for a left-side muscle, −1 for a right-side one.
fn side_sign(m: usize) -> f32 {
    let right = [
        MuscleSegment::Anterior,
        MuscleSegment::Middle,
        MuscleSegment::Posterior,
    ]
    .iter()
    .any(|&s| {
        let i = muscle_index(s, Side::Right);
        m == i || m == i + 1
    });
    if right { -1.0 } else { 1.0 }
}

/// Orders the modes by frequency and shifts each in time so its reference
/// phasor has phase 0.
fn normalise_phases(mut c: AbstractedController) -> AbstractedController {
    c.modes
        .sort_by(|a, b| a.frequency_hz.total_cmp(&b.frequency_hz));
    for mode in &mut c.modes {
        let (mut re, mut im) = (0.0f32, 0.0f32);
        for m in 0..MUSCLE_COUNT {
            let a = mode.amplitudes[m] * side_sign(m);
            re += a * fmath::cos(mode.phases_rad[m]);
            im += a * fmath::sin(mode.phases_rad[m]);
        }
        let shift = fmath::atan2(im, re);
        for p in &mut mode.phases_rad {
            *p = (*p - shift + PI).rem_euclid(TAU) - PI;
        }
    }
    c
}

/// The mirror image (left and right muscles swapped).
fn mirror(c: &AbstractedController) -> AbstractedController {
    AbstractedController {
        mean: mirror_muscles(&c.mean),
        modes: c
            .modes
            .iter()
            .map(|m| FourierMode {
                frequency_hz: m.frequency_hz,
                amplitudes: mirror_muscles(&m.amplitudes),
                phases_rad: mirror_muscles(&m.phases_rad),
            })
            .collect(),
        ..c.clone()
    }
}

/// Interpolates two controllers, `t` in [0, 1] (see the module doc).
pub fn interpolate(
    a: &AbstractedController,
    b: &AbstractedController,
    t: f32,
) -> AbstractedController {
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let lerp = |x: f32, y: f32| x + (y - x) * t;
    let count = a.modes.len().max(b.modes.len());
    let modes = (0..count)
        .map(|j| match (a.modes.get(j), b.modes.get(j)) {
            (Some(x), Some(y)) => FourierMode {
                frequency_hz: lerp(x.frequency_hz, y.frequency_hz),
                amplitudes: std::array::from_fn(|m| lerp(x.amplitudes[m], y.amplitudes[m])),
                phases_rad: std::array::from_fn(|m| {
                    let d = (y.phases_rad[m] - x.phases_rad[m] + PI).rem_euclid(TAU) - PI;
                    x.phases_rad[m] + d * t
                }),
            },
            (Some(x), None) => FourierMode {
                amplitudes: x.amplitudes.map(|v| v * (1.0 - t)),
                ..*x
            },
            (None, Some(y)) => FourierMode {
                amplitudes: y.amplitudes.map(|v| v * t),
                ..*y
            },
            (None, None) => FourierMode {
                frequency_hz: 0.0,
                amplitudes: [0.0; MUSCLE_COUNT],
                phases_rad: [0.0; MUSCLE_COUNT],
            },
        })
        .collect();
    AbstractedController {
        mean: std::array::from_fn(|m| lerp(a.mean[m], b.mean[m])),
        modes,
        energy_fraction: lerp(a.energy_fraction, b.energy_fraction),
        ac_energy_fraction: lerp(a.ac_energy_fraction, b.ac_energy_fraction),
    }
}

/// All muscles relaxed: the map's speed-0 key.
fn resting() -> AbstractedController {
    AbstractedController {
        mean: [0.0; MUSCLE_COUNT],
        modes: Vec::new(),
        energy_fraction: 1.0,
        ac_energy_fraction: 1.0,
    }
}

/// Interpolates along sorted keys (with `zero` at 0) at position `x`.
fn along(zero: &AbstractedController, keys: &[MapKey], x: f32) -> AbstractedController {
    let mut lo_at = 0.0;
    let mut lo = zero;
    for key in keys {
        if x <= key.at {
            let span = key.at - lo_at;
            let t = if span > 0.0 { (x - lo_at) / span } else { 1.0 };
            return interpolate(lo, &key.controller, t);
        }
        lo_at = key.at;
        lo = &key.controller;
    }
    lo.clone()
}

impl LearnedMotorMap {
    /// Builds the map from trained drills (see the module doc). Straight drills
    /// that do not move the fish forward are ignored; a turn drill's measured rate
    /// must have the trained sign to count (a "left" drill that turns right is
    /// ignored).
    pub fn new(controllers: &[LearnedController]) -> Result<Self, LearnedMapError> {
        if controllers
            .iter()
            .any(|c| !c.controller.is_valid() || c.controller.modes.len() > MAX_MODES)
        {
            return Err(LearnedMapError::InvalidController);
        }
        let key = |c: &LearnedController, at: f32| MapKey {
            at,
            controller: normalise_phases(c.controller.clone()),
        };
        let mut straight = Vec::new();
        let mut left = Vec::new();
        let mut right = Vec::new();
        for c in controllers {
            let speed = c.motion.speed_body_lengths_per_sec;
            let rate = c.motion.turn_rate_deg_per_sec;
            match c.role() {
                Role::Straight if speed > 0.0 => straight.push(key(c, speed)),
                Role::Left if rate > 0.0 => left.push(key(c, rate)),
                Role::Right if rate < 0.0 => right.push(key(c, -rate)),
                _ => {}
            }
        }
        if straight.is_empty() {
            return Err(LearnedMapError::NoStraightController);
        }
        let mirrored = |keys: &[MapKey]| -> Vec<MapKey> {
            keys.iter()
                .map(|k| MapKey {
                    at: k.at,
                    controller: mirror(&k.controller),
                })
                .collect()
        };
        if left.is_empty() {
            left = mirrored(&right);
        } else if right.is_empty() {
            right = mirrored(&left);
        }
        for keys in [&mut straight, &mut left, &mut right] {
            keys.sort_by(|a, b| a.at.total_cmp(&b.at));
        }
        let top = straight.last().map_or(0.0, |k| k.at);
        Ok(Self {
            straight,
            left,
            right,
            top_speed_body_lengths_per_sec: top,
        })
    }

    /// The fastest learned straight swim, body lengths per second.
    pub fn top_speed_body_lengths_per_sec(&self) -> f32 {
        self.top_speed_body_lengths_per_sec
    }

    /// The largest learned turn rate to the left (+) or right, degrees per second
    /// (0 if no turn was learned).
    pub fn max_turn_rate_deg_per_sec(&self, left: bool) -> f32 {
        let keys = if left { &self.left } else { &self.right };
        keys.last().map_or(0.0, |k| k.at)
    }

    /// The interpolated controller for `speed_fraction` in [0, 1] of the top
    /// learned speed and `turn_fraction` in [−1, 1] of the largest learned turn
    /// rate (+ = left). NaN counts as 0.
    pub fn controller_for(&self, speed_fraction: f32, turn_fraction: f32) -> AbstractedController {
        let clean = |x: f32, lo: f32| if x.is_finite() { x.clamp(lo, 1.0) } else { 0.0 };
        let (s, r) = (clean(speed_fraction, 0.0), clean(turn_fraction, -1.0));
        let straight = along(
            &resting(),
            &self.straight,
            s * self.top_speed_body_lengths_per_sec,
        );
        let keys = if r >= 0.0 { &self.left } else { &self.right };
        match keys.last() {
            Some(last) if r != 0.0 => along(&straight, keys, r.abs() * last.at),
            _ => straight,
        }
    }
}

/// The learned motor controller: runs a [`LearnedMotorMap`] step by step.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LearnedMotor {
    map: LearnedMotorMap,
    phases_rad: [f32; MAX_MODES],
}

impl LearnedMotor {
    pub fn new(map: LearnedMotorMap) -> Self {
        Self {
            map,
            phases_rad: [0.0; MAX_MODES],
        }
    }

    pub fn map(&self) -> &LearnedMotorMap {
        &self.map
    }

    /// Advances the oscillators by `dt_secs` and returns the 12 muscle
    /// contractions for `speed_fraction` in [0, 1] and `turn_fraction` in [−1, 1]
    /// (+ = left), like `SwimMc::step` and `TurnMc::step` together. Never NaN.
    pub fn step(
        &mut self,
        speed_fraction: f32,
        turn_fraction: f32,
        dt_secs: f32,
    ) -> [f32; MUSCLE_COUNT] {
        self.advance(speed_fraction, turn_fraction, dt_secs);
        self.muscles_at(speed_fraction, turn_fraction, 0.0)
    }

    /// Advances the oscillators by `dt_secs` at the frequencies of the request.
    pub fn advance(&mut self, speed_fraction: f32, turn_fraction: f32, dt_secs: f32) {
        let c = self.map.controller_for(speed_fraction, turn_fraction);
        let dt = finite_non_negative(dt_secs);
        for (mode, phase) in c.modes.iter().zip(&mut self.phases_rad) {
            *phase = (*phase + TAU * mode.frequency_hz * dt).rem_euclid(TAU);
        }
    }

    /// The 12 muscle contractions of the request `t_secs` after the oscillators'
    /// current phases, without advancing them (what the body samples within a
    /// step, see `FishBody::step_with`). Never NaN.
    pub fn muscles_at(
        &self,
        speed_fraction: f32,
        turn_fraction: f32,
        t_secs: f32,
    ) -> [f32; MUSCLE_COUNT] {
        let c = self.map.controller_for(speed_fraction, turn_fraction);
        let t = finite_non_negative(t_secs);
        let mut u = c.mean;
        for (mode, phase) in c.modes.iter().zip(&self.phases_rad) {
            let phase = phase + TAU * mode.frequency_hz * t;
            for ((x, a), p) in u.iter_mut().zip(mode.amplitudes).zip(mode.phases_rad) {
                *x += a * fmath::cos(phase + p);
            }
        }
        u.map(|x| {
            if x.is_finite() {
                x.clamp(0.0, 1.0)
            } else {
                0.0
            }
        })
    }
}

fn finite_non_negative(x: f32) -> f32 {
    if x.is_finite() { x.max(0.0) } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use crate::sim::learning::learned_motor::*;
    use crate::sim::learning::learned_set::LearnedControllerSet;

    pub(crate) fn shipped_map() -> LearnedMotorMap {
        LearnedControllerSet::pretrained()
            .and_then(|s| s.motor_map())
            .expect("the shipped set drives a fish")
    }

    /// The motor at a fixed request, measured like a single controller.
    fn measure_motor(map: &LearnedMotorMap, speed: f32, turn: f32) -> MotionMeasurement {
        let params = BodyParams::default();
        let motor = LearnedMotor::new(map.clone());
        measure_motion_with(BodySpecies::Fish, params, MEASURE_SECS, |t| {
            motor.muscles_at(speed, turn, t)
        })
    }

    #[test]
    fn the_learned_straight_swim_is_at_least_half_as_fast_as_the_hand_tuned_one() {
        let map = shipped_map();
        let learned = measure_motor(&map, 1.0, 0.0);
        let hand =
            measure_hand_tuned_swim(1.0, BodySpecies::Fish, BodyParams::default(), MEASURE_SECS);
        assert!(
            learned.speed_body_lengths_per_sec >= 0.5 * hand.speed_body_lengths_per_sec,
            "learned {learned:?}, hand-tuned {hand:?}"
        );
        assert!(learned.turn_rate_deg_per_sec.abs() < 5.0, "{learned:?}");
        // A slower request swims slower.
        let slow = measure_motor(&map, 0.4, 0.0);
        assert!(
            slow.speed_body_lengths_per_sec < 0.8 * learned.speed_body_lengths_per_sec,
            "slow {slow:?}, full {learned:?}"
        );
    }

    #[test]
    fn learned_turns_turn_the_trained_way() {
        let map = shipped_map();
        let straight = measure_motor(&map, 1.0, 0.0).turn_rate_deg_per_sec;
        let left = measure_motor(&map, 1.0, 1.0).turn_rate_deg_per_sec;
        let right = measure_motor(&map, 1.0, -1.0).turn_rate_deg_per_sec;
        assert!(
            left > straight + 4.0,
            "left {left}°/s, straight {straight}°/s"
        );
        assert!(
            right < straight - 4.0,
            "right {right}°/s, straight {straight}°/s"
        );
        assert!(
            map.max_turn_rate_deg_per_sec(true) > 0.0 && map.max_turn_rate_deg_per_sec(false) > 0.0
        );
    }

    #[test]
    fn the_motor_never_gives_nan_and_keeps_its_rhythm_continuous() {
        let mut motor = LearnedMotor::new(shipped_map());
        let mut previous = motor.step(1.0, 0.0, 0.055);
        for k in 0..400 {
            let (speed, turn) = match k % 4 {
                0 => (f32::NAN, 0.3),
                1 => (2.0, f32::INFINITY),
                2 => (0.5, -7.0),
                _ => (1.0, fmath::sin(k as f32 * 0.01)),
            };
            let u = motor.step(speed, turn, 0.055);
            assert!(u.iter().all(|x| (0.0..=1.0).contains(x)), "{u:?}");
            previous = u;
        }
        assert!(previous.iter().all(|x| x.is_finite()));
        let resting = motor.map().controller_for(0.0, 0.0);
        assert!(
            resting
                .modes
                .iter()
                .all(|m| m.amplitudes.iter().all(|a| *a < 1e-6))
        );
    }

    #[test]
    fn interpolation_blends_amplitude_frequency_and_phase() {
        let mode = |f: f32, a: f32, p: f32| FourierMode {
            frequency_hz: f,
            amplitudes: [a; MUSCLE_COUNT],
            phases_rad: [p; MUSCLE_COUNT],
        };
        let c = |m: FourierMode| AbstractedController {
            mean: [m.amplitudes[0]; MUSCLE_COUNT],
            modes: vec![m],
            energy_fraction: 1.0,
            ac_energy_fraction: 1.0,
        };
        // Phases 170° and −170° are 20° apart: the blend passes through 180°.
        let a = c(mode(1.0, 0.2, 170f32.to_radians()));
        let b = c(mode(2.0, 0.4, (-170f32).to_radians()));
        let mid = interpolate(&a, &b, 0.5);
        assert!((mid.modes[0].frequency_hz - 1.5).abs() < 1e-6);
        assert!((mid.modes[0].amplitudes[3] - 0.3).abs() < 1e-6);
        assert!((mid.modes[0].phases_rad[3].abs() - PI).abs() < 1e-5);
        assert!((mid.mean[0] - 0.3).abs() < 1e-6);
    }

    #[test]
    fn a_map_needs_a_straight_swimming_controller() {
        assert_eq!(
            LearnedMotorMap::new(&[]),
            Err(LearnedMapError::NoStraightController)
        );
    }
}
