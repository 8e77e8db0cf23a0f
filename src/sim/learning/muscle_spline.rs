//! The twelve muscle actuation functions of Tu & Terzopoulos 1994 §4.2 as samples:
//! "discretizing the actuator control functions u(t) by sampling them in the time
//! interval under consideration to obtain the set of discrete samples uᵢ = u(tᵢ) for
//! 1 ≤ i ≤ N (typically, we set N to 15 time samples, and recover the continuous
//! u(t) through linear or cubic spline interpolation of the uᵢ)".
//!
//! The N samples are evenly spaced, the first at t₀ = 0 and the last at the end of
//! the interval. Cubic interpolation is the Catmull-Rom cubic (a C¹ cubic Hermite
//! spline through the samples, end tangents from the one-sided difference): local,
//! so a perturbed sample changes u(t) only over its four neighbouring spans, which
//! keeps annealing moves local. Values are clamped to [0, 1] (a muscle contraction
//! factor, see `body/fish_body.rs`), before and after interpolation.

use serde::{Deserialize, Serialize};

use crate::sim::body::MUSCLE_COUNT;

/// Default number of samples per muscle, N = 15 (the paper's "typically").
pub const DEFAULT_SAMPLE_COUNT: usize = 15;
/// Fewest samples that make a function (two: a straight line).
pub const MIN_SAMPLE_COUNT: usize = 2;
/// Most samples accepted (a file or a UI cannot ask for more), count.
pub const MAX_SAMPLE_COUNT: usize = 256;

/// How u(t) is recovered between samples.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Interpolation {
    /// Straight lines between samples.
    Linear,
    /// Catmull-Rom cubic through the samples (the default: smooth controls).
    #[default]
    Cubic,
}

/// N samples × 12 muscles over an interval of `duration_secs`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MuscleSpline {
    samples: Vec<[f32; MUSCLE_COUNT]>,
    duration_secs: f32,
    interpolation: Interpolation,
}

fn clamp_unit(x: f32) -> f32 {
    if x.is_finite() {
        x.clamp(0.0, 1.0)
    } else {
        0.0
    }
}

impl MuscleSpline {
    /// Every muscle at `value` (clamped to [0, 1]) at all `sample_count` samples
    /// (clamped to [`MIN_SAMPLE_COUNT`], [`MAX_SAMPLE_COUNT`]) over
    /// `duration_secs` (non-finite or non-positive becomes 1 s).
    pub fn constant(
        sample_count: usize,
        duration_secs: f32,
        interpolation: Interpolation,
        value: f32,
    ) -> Self {
        let n = sample_count.clamp(MIN_SAMPLE_COUNT, MAX_SAMPLE_COUNT);
        Self {
            samples: vec![[clamp_unit(value); MUSCLE_COUNT]; n],
            duration_secs: if duration_secs.is_finite() && duration_secs > 0.0 {
                duration_secs
            } else {
                1.0
            },
            interpolation,
        }
    }

    /// From explicit samples (each clamped to [0, 1]); `None` if there are fewer
    /// than [`MIN_SAMPLE_COUNT`] or more than [`MAX_SAMPLE_COUNT`], or the duration
    /// is not a positive finite number of seconds.
    pub fn from_samples(
        samples: Vec<[f32; MUSCLE_COUNT]>,
        duration_secs: f32,
        interpolation: Interpolation,
    ) -> Option<Self> {
        let valid = (MIN_SAMPLE_COUNT..=MAX_SAMPLE_COUNT).contains(&samples.len())
            && duration_secs.is_finite()
            && duration_secs > 0.0;
        if !valid {
            return None;
        }
        Some(Self {
            samples: samples.into_iter().map(|s| s.map(clamp_unit)).collect(),
            duration_secs,
            interpolation,
        })
    }

    /// The samples uᵢ, i = 0..N, each 12 contraction factors in [0, 1].
    pub fn samples(&self) -> &[[f32; MUSCLE_COUNT]] {
        &self.samples
    }

    /// N.
    pub fn sample_count(&self) -> usize {
        self.samples.len()
    }

    /// Length of the interval, seconds.
    pub fn duration_secs(&self) -> f32 {
        self.duration_secs
    }

    pub fn interpolation(&self) -> Interpolation {
        self.interpolation
    }

    /// Time of sample `i`, seconds from the start of the interval.
    pub fn sample_time_secs(&self, i: usize) -> f32 {
        self.duration_secs * i as f32 / (self.samples.len() - 1) as f32
    }

    /// Sets sample `i` of `muscle` (clamped to [0, 1]); out-of-range indices are
    /// ignored.
    pub fn set_sample(&mut self, i: usize, muscle: usize, value: f32) {
        if let Some(s) = self.samples.get_mut(i)
            && let Some(u) = s.get_mut(muscle)
        {
            *u = clamp_unit(value);
        }
    }

    /// Is every sample a finite number in [0, 1]? (Always true for a spline built
    /// here; used to validate a loaded file.)
    pub fn is_valid(&self) -> bool {
        self.duration_secs.is_finite()
            && self.duration_secs > 0.0
            && (MIN_SAMPLE_COUNT..=MAX_SAMPLE_COUNT).contains(&self.samples.len())
            && self
                .samples
                .iter()
                .flatten()
                .all(|u| u.is_finite() && (0.0..=1.0).contains(u))
    }

    /// u(t): the 12 contractions at `t_secs` (clamped to the interval), in [0, 1].
    pub fn value_at(&self, t_secs: f32) -> [f32; MUSCLE_COUNT] {
        let n = self.samples.len();
        let spacing = self.duration_secs / (n - 1) as f32;
        let t = if t_secs.is_finite() {
            t_secs.clamp(0.0, self.duration_secs)
        } else {
            0.0
        };
        let x = t / spacing;
        let i = (x.floor() as usize).min(n - 2);
        let f = (x - i as f32).clamp(0.0, 1.0);
        let (p1, p2) = (&self.samples[i], &self.samples[i + 1]);
        let mut out = [0.0; MUSCLE_COUNT];
        match self.interpolation {
            Interpolation::Linear => {
                for m in 0..MUSCLE_COUNT {
                    out[m] = p1[m] + (p2[m] - p1[m]) * f;
                }
            }
            Interpolation::Cubic => {
                let p0 = &self.samples[i.saturating_sub(1)];
                let p3 = &self.samples[(i + 2).min(n - 1)];
                // Tangents (per span): central differences inside, one-sided at the ends.
                let left_span = if i == 0 { 1.0 } else { 2.0 };
                let right_span = if i + 2 > n - 1 { 1.0 } else { 2.0 };
                let (f2, f3) = (f * f, f * f * f);
                let h00 = 2.0 * f3 - 3.0 * f2 + 1.0;
                let h10 = f3 - 2.0 * f2 + f;
                let h01 = -2.0 * f3 + 3.0 * f2;
                let h11 = f3 - f2;
                for m in 0..MUSCLE_COUNT {
                    let m1 = (p2[m] - p0[m]) / left_span;
                    let m2 = (p3[m] - p1[m]) / right_span;
                    out[m] = h00 * p1[m] + h10 * m1 + h01 * p2[m] + h11 * m2;
                }
            }
        }
        out.map(clamp_unit)
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::learning::muscle_spline::*;

    fn ramp(interpolation: Interpolation) -> MuscleSpline {
        let samples = (0..5).map(|i| [i as f32 / 4.0; MUSCLE_COUNT]).collect();
        MuscleSpline::from_samples(samples, 2.0, interpolation).expect("valid")
    }

    #[test]
    fn both_interpolations_pass_through_the_samples_and_stay_in_range() {
        for interpolation in [Interpolation::Linear, Interpolation::Cubic] {
            let mut s = ramp(interpolation);
            for i in 0..5 {
                let u = s.value_at(s.sample_time_secs(i));
                assert!(
                    (u[3] - i as f32 / 4.0).abs() < 1e-6,
                    "{interpolation:?} {i}"
                );
            }
            // A straight ramp stays a straight ramp.
            assert!((s.value_at(0.25)[0] - 0.125).abs() < 1e-6);
            // Extreme zig-zag: the cubic overshoots, but the values are clamped.
            for i in 0..5 {
                s.set_sample(i, 0, (i % 2) as f32);
            }
            for k in 0..=200 {
                let u = s.value_at(k as f32 * 0.01);
                assert!(u.iter().all(|x| (0.0..=1.0).contains(x)));
            }
        }
    }

    #[test]
    fn bad_inputs_are_refused_or_clamped() {
        assert!(
            MuscleSpline::from_samples(vec![[0.5; MUSCLE_COUNT]], 1.0, Interpolation::Cubic)
                .is_none()
        );
        assert!(
            MuscleSpline::from_samples(
                vec![[0.5; MUSCLE_COUNT]; 3],
                f32::NAN,
                Interpolation::Cubic
            )
            .is_none()
        );
        let s = MuscleSpline::from_samples(
            vec![[f32::NAN; MUSCLE_COUNT]; 3],
            1.0,
            Interpolation::Linear,
        )
        .expect("clamped");
        assert!(s.is_valid());
        assert_eq!(s.value_at(f32::NAN), [0.0; MUSCLE_COUNT]);
        let c = MuscleSpline::constant(0, -1.0, Interpolation::Cubic, 2.0);
        assert_eq!(c.sample_count(), MIN_SAMPLE_COUNT);
        assert_eq!(c.value_at(0.5), [1.0; MUSCLE_COUNT]);
    }
}
