//! Motor controllers, Tu & Terzopoulos 1994 §3.3: swim-MC(speed) → {r1, s1, r2, s2},
//! the contraction amplitude r and frequency s of the anterior (1) and posterior (2)
//! swimming segments (here the middle and posterior muscle segments, see
//! `body_layout.rs`). Opposite sides are exactly out of phase: u_left = r·max(0, sin φ),
//! u_right = r·max(0, −sin φ), so their difference is a pure sine of amplitude r.
//!
//! # Deviation from the paper: posterior lag 30°, not 180°
//! The paper lags the posterior segment 180° behind the anterior one. With this body
//! (two short, adjacent actuated segments, each 0.19 body lengths long) a 180° lag
//! makes a standing S-wave and gives almost no thrust: measured 0.012, 0.017 and
//! 0.013 body lengths/s at 1, 2 and 3 Hz. A small lag makes a travelling wave
//! (resistive thrust needs one). Measured at 3 Hz, 40 s runs, k = 30 with 5
//! substeps (a setting tried on the way): lag 30° 0.50, 45° 0.49, 60° 0.47,
//! 90° 0.41 body lengths/s; with the defaults (k = 40, 8 substeps) 30° 0.60 and
//! 45° 0.59. Default 30°, tuned. The lag is a parameter.
//!
//! # Measured speed table (tuning routine: `tests::speed_table`, 26-unit fish,
//! default `BodyParams` (k = 40 paper time units per second, 8 substeps of the
//! fixed Δt = 0.055 s), lag 30°, 60 s runs, speed over the last 30 s)
//!
//! | amplitude r1 = r2 | frequency s (Hz) | speed (body lengths/s) |
//! |-------------------|------------------|------------------------|
//! | 1.0               | 0.5              | 0.055                  |
//! | 1.0               | 1.0              | 0.140                  |
//! | 1.0               | 1.5              | 0.257                  |
//! | 1.0               | 2.0              | 0.395                  |
//! | 1.0               | 2.5              | 0.527                  |
//! | 1.0               | 3.0              | 0.630 (top, ŝ)         |
//! | 1.0               | 4.0              | 0.736 (saturating)     |
//! | 1.0               | 5.0              | 0.744                  |
//! | 0.75              | 3.0              | 0.458                  |
//! | 0.5               | 3.0              | 0.272                  |
//! | 0.25              | 3.0              | 0.108                  |
//!
//! (With the tail-fin tips braced to ring 4, `body_layout.rs`. Before the brace:
//! 0.600 at 3 Hz and 0.662 at 4 and 5 Hz. The scenes still take 0.6 body
//! lengths/s as the top speed, `motor_bridge::TOP_SPEED_BODY_LENGTHS_PER_SEC`, so
//! a fish at full thrust swims about 5 % faster than its nominal top.)
//!
//! Speed is proportional to amplitude and grows about linearly with frequency up to
//! about 3 Hz, then saturates (4 and 5 Hz give 0.74), as the paper (after
//! Webb) reports "below certain threshold values". That is 0.2 body lengths per
//! tail beat at the top, a third of a real fish's 0.6–0.7 (no reactive/added-mass
//! force in the paper's model, a small tail fin). Maximal parameters:
//! r̂1 = r̂2 = 1, ŝ1 = ŝ2 = 3 Hz (inside the 1–3 Hz of real cruising fish).
//! The turn-MCs are in `turn_mc.rs`.

use serde::{Deserialize, Serialize};
use std::f32::consts::{FRAC_PI_6, TAU};

use super::body_layout::{MUSCLE_COUNT, MuscleSegment, Side, muscle_index};

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
        anterior_frequency_hz: 3.0,
        posterior_amplitude: 1.0,
        posterior_frequency_hz: 3.0,
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
    /// Speed is proportional to amplitude (measured), so the amplitudes are scaled
    /// and the frequencies kept at their maxima, like the paper's example
    /// {0.8 r̂1, ŝ1, 0.7 r̂2, ŝ2}. NaN counts as 0.
    pub fn params_for_speed(&self, speed_fraction: f32) -> SwimParams {
        let k = if speed_fraction.is_finite() {
            speed_fraction.clamp(0.0, 1.0)
        } else {
            0.0
        };
        SwimParams {
            anterior_amplitude: k * self.max.anterior_amplitude,
            posterior_amplitude: k * self.max.posterior_amplitude,
            ..self.max
        }
    }

    /// Advances the oscillators by `dt_secs` and returns the 12 muscle contractions
    /// (turning-only anterior segment left relaxed). Phases are continuous when the
    /// frequency changes.
    pub fn step(&mut self, params: &SwimParams, dt_secs: f32) -> [f32; MUSCLE_COUNT] {
        let advance = |phase: &mut f32, f: f32| {
            let f = if f.is_finite() { f.max(0.0) } else { 0.0 };
            *phase = (*phase + TAU * f * dt_secs).rem_euclid(TAU);
        };
        advance(&mut self.anterior_phase_rad, params.anterior_frequency_hz);
        advance(&mut self.posterior_phase_rad, params.posterior_frequency_hz);
        let mut u = [0.0; MUSCLE_COUNT];
        let a = self.anterior_phase_rad.sin();
        let p = (self.posterior_phase_rad - self.posterior_lag_rad).sin();
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
