//! Motor controllers, Tu & Terzopoulos 1994 §3.3: swim-MC(speed) → {r1, s1, r2, s2},
//! the contraction amplitude r and frequency s of the anterior (1) and posterior (2)
//! swimming segments (here the middle and posterior muscle segments, see
//! `body_layout.rs`). Opposite sides are exactly out of phase: u_left = r·max(0, sin φ),
//! u_right = r·max(0, −sin φ), so their difference is a pure sine of amplitude r.
//!
//! # Deviation from the paper: posterior lag 30°, not 180°
//! The paper lags the posterior segment 180° behind the anterior one. With this body
//! (two short, adjacent actuated segments, each 0.19 body lengths long) a 180° lag
//! makes a standing S-wave and no thrust. Measured on the default body at the top
//! setting, 2.3 Hz (census `wave-table`): lag 0° 0.578, 30° 0.585, 90° 0.416,
//! 180° −0.006 body lengths/s. So the lag between the two segments does not make
//! the travelling wave: 0° swims almost as fast as 30°. The wave comes from the
//! passive tail, which the water drags behind the actuated body: the tail fin's
//! sideways motion lags the last body ring's by about 40° at every frequency from 1
//! to 4.5 Hz. Default 30°, kept (the lag is a parameter).
//!
//! # Speed (census `speed-table`; the table is in `docs/fish-body.md`, "Swimming")
//! On the default body (12 BDF2 substeps per 0.055 s step, converged, tail fin
//! braced) full amplitude swims 0.152 / 0.468 / 0.585 / 0.826 body lengths/s at
//! 1 / 2 / 2.3 / 3 Hz: about linearly with frequency up to 3 Hz, 0.23–0.28 body
//! lengths per beat. Above 3 Hz the swimming is erratic (4 Hz: 0.63–0.86 depending
//! on the run's length) and at 5 Hz the passive tail fails. That failure is a
//! property of this model's light, passive tail in the one-sided water force, and
//! where it lies depends on details (spring damping, skin, fin brace); it is not
//! Webb's biological threshold, and the paper's "below certain threshold values" is
//! not reproduced by any mechanism of the model. Speed grows faster than amplitude
//! ([`SPEED_AT_AMPLITUDE`]), so swim-MC(speed) reads the amplitude off that curve.
//! Maximal parameters: r̂1 = r̂2 = 1, ŝ1 = ŝ2 = 2.3 Hz, chosen: the top speed,
//! 0.585 body lengths/s, is within 3 % of the 0.6 that every scene was tuned to
//! (`motor_bridge::TOP_SPEED_BODY_LENGTHS_PER_SEC`), inside the 1–3 Hz of real
//! cruising fish, well below the cliff; at 3 Hz (0.779) the turns converged more
//! slowly and held-bend steering was weak on the earlier body (`fish_body.rs`,
//! "Convergence"). The turn-MCs are in `turn_mc.rs`.

use crate::sim::common::fmath;
use serde::{Deserialize, Serialize};
use std::f32::consts::{FRAC_PI_6, TAU};

use crate::sim::body::body_layout::{MUSCLE_COUNT, MuscleSegment, Side, muscle_index};

/// Amplitudes (contraction factor, [0, 1]) and frequencies (Hz) of the two swimming
/// segments.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SwimParams {
    /// r1: anterior swimming (middle muscle) segment amplitude, [0, 1].
    pub anterior_amplitude: f32,
    /// s1: anterior swimming segment frequency, Hz.
    pub anterior_frequency_hz: f32,
    /// r2: posterior segment amplitude, [0, 1].
    pub posterior_amplitude: f32,
    /// s2: posterior segment frequency, Hz.
    pub posterior_frequency_hz: f32,
}

impl SwimParams {
    /// Maximal parameters (r̂1, ŝ1, r̂2, ŝ2): the fastest swimming found by the
    /// tuning routine (see the module doc).
    pub const MAX: Self = Self {
        anterior_amplitude: 1.0,
        anterior_frequency_hz: 2.3,
        posterior_amplitude: 1.0,
        posterior_frequency_hz: 2.3,
    };
}

/// The swim motor controller: maps a speed request to [`SwimParams`] and produces
/// muscle contractions step by step.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SwimMc {
    /// Parameters at full speed.
    pub max: SwimParams,
    /// Phase lag of the posterior segment behind the anterior one, radians.
    /// Default π/6 (30°), tuned (the paper says π; see the module doc).
    pub posterior_lag_rad: f32,
    anterior_phase_rad: f32,
    posterior_phase_rad: f32,
}

impl Default for SwimMc {
    fn default() -> Self {
        Self {
            max: SwimParams::MAX,
            posterior_lag_rad: FRAC_PI_6,
            anterior_phase_rad: 0.0,
            posterior_phase_rad: 0.0,
        }
    }
}

impl SwimMc {
    /// swim-MC(speed): `speed_fraction` in [0, 1] of the top speed → parameters.
    /// The frequencies stay at their maxima and the amplitudes are scaled, like
    /// the paper's example {0.8 r̂1, ŝ1, 0.7 r̂2, ŝ2}; the scale is read off the
    /// measured speed of each amplitude ([`SPEED_AT_AMPLITUDE`]), so a fish asked
    /// for 0.3 of its top speed swims at 0.3, not at the 0.2 that 0.3 of the
    /// amplitude gives. NaN counts as 0.
    pub fn params_for_speed(&self, speed_fraction: f32) -> SwimParams {
        let a = amplitude_for_speed(speed_fraction);
        SwimParams {
            anterior_amplitude: a * self.max.anterior_amplitude,
            posterior_amplitude: a * self.max.posterior_amplitude,
            ..self.max
        }
    }

    /// Advances the oscillators by `dt_secs` and returns the 12 muscle contractions
    /// (turning-only anterior segment left relaxed). Phases are continuous when the
    /// frequency changes.
    pub fn step(&mut self, params: &SwimParams, dt_secs: f32) -> [f32; MUSCLE_COUNT] {
        self.advance(params, dt_secs);
        self.muscles_at(params, 0.0)
    }

    /// Phase of the anterior (middle-segment) oscillator, radians in [0, 2π): the
    /// left side contracts while its sine is positive.
    pub fn anterior_phase_rad(&self) -> f32 {
        self.anterior_phase_rad
    }

    /// Advances the oscillators by `dt_secs` (continuous when the frequency
    /// changes).
    pub fn advance(&mut self, params: &SwimParams, dt_secs: f32) {
        self.anterior_phase_rad = phase_after(
            self.anterior_phase_rad,
            params.anterior_frequency_hz,
            dt_secs,
        );
        self.posterior_phase_rad = phase_after(
            self.posterior_phase_rad,
            params.posterior_frequency_hz,
            dt_secs,
        );
    }

    /// The 12 muscle contractions `t_secs` after the oscillators' current phase,
    /// without advancing them (what the body samples within a step, see
    /// `FishBody::step_with`).
    pub fn muscles_at(&self, params: &SwimParams, t_secs: f32) -> [f32; MUSCLE_COUNT] {
        let mut u = [0.0; MUSCLE_COUNT];
        let a = fmath::sin(phase_after(
            self.anterior_phase_rad,
            params.anterior_frequency_hz,
            t_secs,
        ));
        let p = fmath::sin(
            phase_after(
                self.posterior_phase_rad,
                params.posterior_frequency_hz,
                t_secs,
            ) - self.posterior_lag_rad,
        );
        set_side_pair(&mut u, MuscleSegment::Middle, params.anterior_amplitude, a);
        set_side_pair(
            &mut u,
            MuscleSegment::Posterior,
            params.posterior_amplitude,
            p,
        );
        u
    }
}

/// Straight-swimming speed of the default body at amplitude 0, 0.05, …, 1.0 of
/// r̂1 = r̂2 (frequencies ŝ), as a fraction of its speed at full amplitude
/// (census `amplitude-speed-curve`: a 0.5 m fish, 40 s runs,
/// speed over the last 20 s; 0.292 m/s = 0.584 body lengths/s at full
/// amplitude). Speed grows faster than amplitude: half the amplitude swims at
/// 0.38 of the speed, a fifth at 0.11. (On the earlier, unconverged body speed
/// was about proportional to amplitude.)
pub const SPEED_AT_AMPLITUDE: [f32; 21] = [
    0.0, 0.021, 0.046, 0.075, 0.108, 0.145, 0.186, 0.230, 0.278, 0.329, 0.382, 0.439, 0.498, 0.558,
    0.621, 0.684, 0.748, 0.812, 0.876, 0.939, 1.0,
];

/// The amplitude (fraction of r̂) whose straight-swimming speed is
/// `speed_fraction` of the full-amplitude speed: [`SPEED_AT_AMPLITUDE`]
/// inverted by linear interpolation. Clamped to [0, 1]; NaN counts as 0.
pub fn amplitude_for_speed(speed_fraction: f32) -> f32 {
    let k = if speed_fraction.is_finite() {
        speed_fraction.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let step = 1.0 / (SPEED_AT_AMPLITUDE.len() - 1) as f32;
    for (i, pair) in SPEED_AT_AMPLITUDE.windows(2).enumerate() {
        let (lo, hi) = (pair[0], pair[1]);
        if k <= hi {
            let t = if hi > lo { (k - lo) / (hi - lo) } else { 0.0 };
            return (i as f32 + t) * step;
        }
    }
    1.0
}

/// An oscillator's phase `dt_secs` after `phase_rad` at `frequency_hz` (negative or
/// NaN counts as 0), wrapped to [0, 2π).
fn phase_after(phase_rad: f32, frequency_hz: f32, dt_secs: f32) -> f32 {
    let f = if frequency_hz.is_finite() {
        frequency_hz.max(0.0)
    } else {
        0.0
    };
    (phase_rad + TAU * f * dt_secs).rem_euclid(TAU)
}

/// How the motor controllers feed the body within a step of Δt.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ControlSampling {
    /// Once per step; the body ramps linearly from the last command to the new one
    /// across its substeps (`FishBody::step`).
    PerStep,
    /// At the end of every substep (`FishBody::step_with`).
    #[default]
    PerSubstep,
}

/// Left side contracts with r·max(0, w), right side with r·max(0, −w).
fn set_side_pair(u: &mut [f32; MUSCLE_COUNT], segment: MuscleSegment, amplitude: f32, wave: f32) {
    let r = if amplitude.is_finite() {
        amplitude.clamp(0.0, 1.0)
    } else {
        0.0
    };
    for (side, value) in [(Side::Left, wave.max(0.0)), (Side::Right, (-wave).max(0.0))] {
        let i = muscle_index(segment, side);
        u[i] = r * value;
        u[i + 1] = r * value;
    }
}
