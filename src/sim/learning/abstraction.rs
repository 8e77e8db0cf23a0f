//! Abstraction of high-level controllers, Tu & Terzopoulos 1994 §4.3: represent the
//! learned control functions "as accurately as possible in the form
//! u(t) ≈ Σ_{i=0}^{M} αᵢ Bᵢ(t)" in a Fourier basis found by the short-time FFT,
//! keeping "a small set of M significant basis functions, usually 1 or 2".
//!
//! Procedure ([`abstract_controls`]):
//! 1. Sample the learned u(t) at `resample_count` even times over the window (the
//!    training interval from `window_start_fraction` of it to its end).
//! 2. Fourier transform of each muscle with its mean removed, zero-padded
//!    `zero_padding`-fold so peaks fall between the window's 1/T bins too; sum the
//!    power over the twelve muscles: the spectrum of the controller.
//! 3. The M highest peaks of that spectrum (at least 1/T apart, i.e. one main lobe;
//!    each refined by a parabola through its three grid points) are the primary
//!    modes. One set of frequencies for all twelve muscles, chosen:
//!    a swimming wave is a coordination of muscles at one rhythm, and per-muscle
//!    frequencies would drift out of phase when run for longer than the window.
//! 4. Each muscle's coefficients at those frequencies by least squares on
//!    B₀ = 1 (the mean), cos and sin of each mode: amplitude and phase per muscle
//!    and mode, u_m(t) ≈ ū_m + Σⱼ A_mj cos(2π fⱼ t + φ_mj), t from the start of the
//!    interval.
//!
//! Energy kept ([`AbstractedController::energy_fraction`]) = 1 − ‖u − û‖² / ‖u‖²
//! over the window and all muscles (B₀ counts as a basis function, as in the
//! paper's sum from i = 0); [`AbstractedController::ac_energy_fraction`] is the
//! same with the means removed (how well the modes capture the oscillation alone).

use crate::sim::common::fmath;
use serde::{Deserialize, Serialize};
use std::f32::consts::TAU;

use crate::sim::body::MUSCLE_COUNT;
use crate::sim::learning::muscle_spline::MuscleSpline;

/// Spectral power per sample and muscle below which a peak is rounding noise, not
/// a mode (an amplitude of about 10⁻⁴).
const NEGLIGIBLE_POWER: f32 = 1.0e-8;

/// Largest sample count and zero padding honoured: the directly evaluated
/// spectrum costs count × padded / 2 products per muscle (at most 1024 × 8192).
const MAX_RESAMPLE_COUNT: usize = 1024;
const MAX_ZERO_PADDING: usize = 16;

/// Settings of the change of basis.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct AbstractionSettings {
    /// M, sinusoidal modes kept (besides the mean). Default 2 (paper: "usually 1 or
    /// 2"); clamped to 0..=4.
    pub modes: usize,
    /// Samples of u(t) over the window, count. Default 128, chosen: 51 per second
    /// over the 2.5 s interval, far above the splines' highest frequency;
    /// clamped to 16..=1024.
    pub resample_count: usize,
    /// Zero padding factor of the Fourier transform, count. Default 8, chosen:
    /// frequency grid 1/(8T) (0.05 Hz for T = 2.5 s); clamped to 1..=16.
    pub zero_padding: usize,
    /// Where the window starts, as a fraction of the interval. Default 0.3,
    /// tuned: the fish starts from rest and its first strokes differ from its
    /// cruising rhythm; the short-time window covers the last 70 % (1.7 s of the
    /// default 2.5 s interval, three to four beats). Measured on a straight swim
    /// (2000 steps, seed 1, M = 2): 90.1 % of the energy kept over the whole
    /// interval, 91.4 % over the last 70 %.
    pub window_start_fraction: f32,
}

impl Default for AbstractionSettings {
    fn default() -> Self {
        Self {
            modes: 2,
            resample_count: 128,
            zero_padding: 8,
            window_start_fraction: 0.3,
        }
    }
}

/// One sinusoidal basis function of a controller: the same frequency for every
/// muscle, each muscle with its own amplitude and phase.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FourierMode {
    pub frequency_hz: f32,
    /// A_m, contraction factor.
    pub amplitudes: [f32; MUSCLE_COUNT],
    /// φ_m, radians: this mode contributes A_m cos(2π f t + φ_m).
    pub phases_rad: [f32; MUSCLE_COUNT],
}

impl FourierMode {
    /// This mode's contribution at `t_secs` (unclamped; the centre row of Fig. 8).
    pub fn value_at(&self, t_secs: f32) -> [f32; MUSCLE_COUNT] {
        let theta = TAU * self.frequency_hz * t_secs;
        std::array::from_fn(|m| self.amplitudes[m] * fmath::cos(theta + self.phases_rad[m]))
    }

    /// Is everything finite and the amplitudes non-negative?
    pub fn is_valid(&self) -> bool {
        self.frequency_hz.is_finite()
            && self.frequency_hz >= 0.0
            && self.amplitudes.iter().all(|a| a.is_finite() && *a >= 0.0)
            && self.phases_rad.iter().all(|p| p.is_finite())
    }
}

/// A compact controller: a mean and M sinusoids per muscle.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AbstractedController {
    /// ū_m, the B₀ coefficient of each muscle.
    pub mean: [f32; MUSCLE_COUNT],
    /// The primary modes, most energetic first.
    pub modes: Vec<FourierMode>,
    /// Share of the learned controls' energy the abstraction keeps (with the mean).
    pub energy_fraction: f32,
    /// Share of the learned controls' oscillation (mean removed) the modes keep.
    pub ac_energy_fraction: f32,
}

impl AbstractedController {
    /// The abstracted contractions at `t_secs`, clamped to [0, 1] (the lower row of
    /// Fig. 8). Defined for all t: the controller is periodic in its modes.
    pub fn value_at(&self, t_secs: f32) -> [f32; MUSCLE_COUNT] {
        let mut u = self.mean;
        for mode in &self.modes {
            for (x, y) in u.iter_mut().zip(mode.value_at(t_secs)) {
                *x += y;
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

    /// Every number finite, amplitudes non-negative?
    pub fn is_valid(&self) -> bool {
        self.mean.iter().all(|x| x.is_finite())
            && self.modes.iter().all(FourierMode::is_valid)
            && self.energy_fraction.is_finite()
            && self.ac_energy_fraction.is_finite()
    }
}

/// The change of basis and what the UI plots (Fig. 8).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Abstraction {
    pub controller: AbstractedController,
    /// Times of the resampled window, seconds from the start of the interval.
    pub times_secs: Vec<f32>,
    /// The learned controls at those times (upper row of Fig. 8).
    pub learned: Vec<[f32; MUSCLE_COUNT]>,
    /// The spectrum: frequencies (Hz) and power summed over the muscles, from the
    /// first non-zero bin to the Nyquist frequency.
    pub spectrum_hz: Vec<f32>,
    pub spectrum_power: Vec<f32>,
}

/// Solves the small symmetric system `a x = b` (Gaussian elimination with partial
/// pivoting); `None` if singular.
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
    let n = b.len();
    for col in 0..n {
        let pivot = (col..n).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[pivot][col].abs() < 1e-9 {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        let pivot_row = a[col].clone();
        for row in col + 1..n {
            let f = a[row][col] / pivot_row[col];
            for (x, p) in a[row][col..].iter_mut().zip(&pivot_row[col..]) {
                *x -= f * p;
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let s: f64 = (row + 1..n).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// The power spectrum of the twelve muscles' zero-mean samples, zero-padded to
/// `padded` points and summed over the muscles: Σ_m |X_m(k)|² for the bins
/// k = 0 … padded/2, with X_m(k) = Σ_n (u_m(n) − ū_m) e^(−2πi·k·n/padded).
///
/// The transform is evaluated directly, bin by bin, over the samples only (the
/// zero padding adds no terms): count × (padded/2 + 1) products per muscle,
/// about 0.8 million for all twelve at the defaults, a few milliseconds once
/// per learned controller. A fast Fourier transform gives the same numbers to
/// rounding, at the price of a general FFT library in the download (it was
/// rustfft: 91 KB of the gzipped wasm, docs/benchmarks.md). Sums in f64.
fn spectrum_power(
    learned: &[[f32; MUSCLE_COUNT]],
    means: &[f32; MUSCLE_COUNT],
    padded: usize,
) -> Vec<f32> {
    let half = padded / 2;
    // e^(−2πi·j/padded) for j < padded; the phase k·n wraps modulo padded.
    let twiddles: Vec<(f64, f64)> = (0..padded)
        .map(|j| {
            let th = std::f64::consts::TAU * j as f64 / padded as f64;
            (fmath::cos_f64(th), -fmath::sin_f64(th))
        })
        .collect();
    let centred: Vec<[f64; MUSCLE_COUNT]> = learned
        .iter()
        .map(|u| std::array::from_fn(|m| f64::from(u[m] - means[m])))
        .collect();
    (0..=half)
        .map(|k| {
            let mut re = [0.0f64; MUSCLE_COUNT];
            let mut im = [0.0f64; MUSCLE_COUNT];
            let mut j = 0usize;
            for x in &centred {
                let (c, s) = twiddles[j];
                for m in 0..MUSCLE_COUNT {
                    re[m] += x[m] * c;
                    im[m] += x[m] * s;
                }
                j = (j + k) % padded;
            }
            re.iter().zip(&im).map(|(r, i)| r * r + i * i).sum::<f64>() as f32
        })
        .collect()
}

/// The abstraction of `controls` (see the module doc). Deterministic, never NaN.
pub fn abstract_controls(controls: &MuscleSpline, settings: &AbstractionSettings) -> Abstraction {
    let count = settings.resample_count.clamp(16, MAX_RESAMPLE_COUNT);
    let padded = count * settings.zero_padding.clamp(1, MAX_ZERO_PADDING);
    let start_secs = controls.duration_secs()
        * if settings.window_start_fraction.is_finite() {
            settings.window_start_fraction.clamp(0.0, 0.9)
        } else {
            0.0
        };
    let window_secs = controls.duration_secs() - start_secs;
    let dt = window_secs / count as f32;
    let times_secs: Vec<f32> = (0..count).map(|k| start_secs + k as f32 * dt).collect();
    let learned: Vec<[f32; MUSCLE_COUNT]> =
        times_secs.iter().map(|&t| controls.value_at(t)).collect();
    let mut means = [0.0f32; MUSCLE_COUNT];
    for u in &learned {
        for m in 0..MUSCLE_COUNT {
            means[m] += u[m] / count as f32;
        }
    }

    // Spectrum of the controller (power summed over muscles).
    let half = padded / 2;
    let power = spectrum_power(&learned, &means, padded);
    let bin_hz = 1.0 / (padded as f32 * dt);
    let spectrum_hz: Vec<f32> = (1..=half).map(|k| k as f32 * bin_hz).collect();
    let spectrum_power: Vec<f32> = power[1..=half].to_vec();

    // The M highest peaks, at least one main lobe (1/window) apart.
    let lobe_bins = settings.zero_padding.clamp(1, MAX_ZERO_PADDING);
    let mut peaks: Vec<usize> = (1..half)
        .filter(|&k| {
            power[k] > NEGLIGIBLE_POWER * (count * MUSCLE_COUNT) as f32
                && power[k] >= power[k - 1]
                && power[k] >= power[k + 1]
        })
        .collect();
    peaks.sort_by(|&a, &b| power[b].total_cmp(&power[a]).then(a.cmp(&b)));
    let mut chosen: Vec<usize> = Vec::new();
    for k in peaks {
        if chosen.len() >= settings.modes.min(4) {
            break;
        }
        if chosen.iter().all(|&c| c.abs_diff(k) >= lobe_bins) {
            chosen.push(k);
        }
    }
    // Each peak refined between grid points by the parabola through its bin and
    // its two neighbours (the window is only a few beats long).
    let frequencies: Vec<f32> = chosen
        .iter()
        .map(|&k| {
            let (a, b, c) = (power[k - 1], power[k], power[k + 1]);
            let curvature = a - 2.0 * b + c;
            let offset = if curvature < 0.0 {
                (0.5 * (a - c) / curvature).clamp(-0.5, 0.5)
            } else {
                0.0
            };
            (k as f32 + offset) * bin_hz
        })
        .collect();

    // Least squares per muscle on [1, cos, sin, cos, sin, …].
    let dim = 1 + 2 * frequencies.len();
    let basis = |t: f32| -> Vec<f64> {
        let mut b = vec![1.0f64];
        for f in &frequencies {
            let th = f64::from(TAU * f * t);
            b.push(fmath::cos_f64(th));
            b.push(fmath::sin_f64(th));
        }
        b
    };
    let rows: Vec<Vec<f64>> = times_secs.iter().map(|&t| basis(t)).collect();
    let mut normal = vec![vec![0.0f64; dim]; dim];
    for r in &rows {
        for i in 0..dim {
            for j in 0..dim {
                normal[i][j] += r[i] * r[j];
            }
        }
    }
    let mut mean = means;
    let mut modes: Vec<FourierMode> = frequencies
        .iter()
        .map(|&f| FourierMode {
            frequency_hz: f,
            amplitudes: [0.0; MUSCLE_COUNT],
            phases_rad: [0.0; MUSCLE_COUNT],
        })
        .collect();
    for m in 0..MUSCLE_COUNT {
        let mut rhs = vec![0.0f64; dim];
        for (r, u) in rows.iter().zip(&learned) {
            for i in 0..dim {
                rhs[i] += r[i] * f64::from(u[m]);
            }
        }
        if let Some(x) = solve(normal.clone(), rhs) {
            mean[m] = x[0] as f32;
            for (j, mode) in modes.iter_mut().enumerate() {
                let (a, b) = (x[1 + 2 * j], x[2 + 2 * j]);
                // a cos θ + b sin θ = A cos(θ + φ) with A = √(a² + b²), φ = atan2(−b, a).
                mode.amplitudes[m] = fmath::hypot_f64(a, b) as f32;
                mode.phases_rad[m] = fmath::atan2_f64(-b, a) as f32;
            }
        }
    }
    let mut controller = AbstractedController {
        mean,
        modes,
        energy_fraction: 0.0,
        ac_energy_fraction: 0.0,
    };
    let (mut total, mut ac_total, mut residual) = (0.0f64, 0.0f64, 0.0f64);
    for (&t, u) in times_secs.iter().zip(&learned) {
        let mut fit = controller.mean;
        for mode in &controller.modes {
            for (x, y) in fit.iter_mut().zip(mode.value_at(t)) {
                *x += y;
            }
        }
        for m in 0..MUSCLE_COUNT {
            total += fmath::powi_f64(f64::from(u[m]), 2);
            ac_total += fmath::powi_f64(f64::from(u[m] - means[m]), 2);
            residual += fmath::powi_f64(f64::from(u[m] - fit[m]), 2);
        }
    }
    let fraction = |whole: f64| {
        if whole > 0.0 {
            (1.0 - residual / whole).clamp(0.0, 1.0) as f32
        } else {
            1.0
        }
    };
    controller.energy_fraction = fraction(total);
    controller.ac_energy_fraction = fraction(ac_total);
    Abstraction {
        controller,
        times_secs,
        learned,
        spectrum_hz,
        spectrum_power,
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::learning::abstraction::*;
    use crate::sim::learning::muscle_spline::Interpolation;

    #[test]
    fn a_sampled_sine_is_recovered_as_one_mode() {
        // 1.2 Hz sine on the left tail muscles, its mirror on the right, 2.5 s.
        let n = 61;
        let samples = (0..n)
            .map(|i| {
                let t = 2.5 * i as f32 / (n - 1) as f32;
                let w = fmath::sin(TAU * 1.2 * t);
                let mut u = [0.0; MUSCLE_COUNT];
                for m in 8..10 {
                    u[m] = 0.5 + 0.4 * w;
                    u[m + 2] = 0.5 - 0.4 * w;
                }
                u
            })
            .collect();
        let spline = MuscleSpline::from_samples(samples, 2.5, Interpolation::Cubic).expect("valid");
        let a = abstract_controls(
            &spline,
            &AbstractionSettings {
                modes: 1,
                ..AbstractionSettings::default()
            },
        );
        let c = &a.controller;
        assert!(
            (c.modes[0].frequency_hz - 1.2).abs() < 0.03,
            "{:?}",
            c.modes[0]
        );
        assert!((c.modes[0].amplitudes[8] - 0.4).abs() < 0.03);
        let opposite = (c.modes[0].phases_rad[8] - c.modes[0].phases_rad[10]).rem_euclid(TAU);
        assert!((opposite - std::f32::consts::PI).abs() < 0.05, "{opposite}");
        assert!(
            c.ac_energy_fraction > 0.97 && c.energy_fraction > 0.99,
            "{c:?}"
        );
        assert!(c.is_valid());
        assert_eq!(a.learned.len(), a.times_secs.len());
        assert!(c.value_at(1.0).iter().all(|u| (0.0..=1.0).contains(u)));
    }

    #[test]
    fn the_direct_spectrum_holds_parsevals_sum_and_puts_a_whole_cycle_sine_in_its_bin() {
        // 128 samples zero-padded to 1024: a cosine of 5 whole cycles over the
        // samples falls on bin 5 × 8 = 40 of one muscle, with |X|² = (A·n/2)².
        let (count, padded, cycles) = (128usize, 1024usize, 5usize);
        let learned: Vec<[f32; MUSCLE_COUNT]> = (0..count)
            .map(|n| {
                let mut u = [0.0; MUSCLE_COUNT];
                u[3] = 0.3 * fmath::cos(TAU * (cycles * n) as f32 / count as f32);
                // An irregular signal on another muscle, for the sum below.
                u[7] = fmath::sin(0.37 * n as f32 * n as f32) * 0.2;
                u
            })
            .collect();
        let mut means = [0.0f32; MUSCLE_COUNT];
        for u in &learned {
            for m in 0..MUSCLE_COUNT {
                means[m] += u[m] / count as f32;
            }
        }
        let power = spectrum_power(&learned, &means, padded);
        assert_eq!(power.len(), padded / 2 + 1);
        // Parseval over the padded transform of real signals: |X₀|² + 2Σ|X_k|²
        // (0 < k < N/2) + |X_{N/2}|² = N Σ x².
        let energy: f64 = learned
            .iter()
            .map(|u| {
                (0..MUSCLE_COUNT)
                    .map(|m| {
                        let x = f64::from(u[m] - means[m]);
                        x * x
                    })
                    .sum::<f64>()
            })
            .sum();
        let half = padded / 2;
        let spectral: f64 = (0..=half)
            .map(|k| f64::from(power[k]) * if k == 0 || k == half { 1.0 } else { 2.0 })
            .sum();
        let relative = (spectral - padded as f64 * energy).abs() / (padded as f64 * energy);
        assert!(relative < 1e-5, "Parseval off by {relative}");
        // Muscle 3 alone: its peak at bin 40 with (0.3 · 128 / 2)² = 368.64.
        let mut only = learned.clone();
        for u in &mut only {
            u[7] = 0.0;
        }
        let mut m3 = [0.0; MUSCLE_COUNT];
        m3[3] = means[3];
        let p = spectrum_power(&only, &m3, padded);
        let peak = (0..p.len())
            .max_by(|&a, &b| p[a].total_cmp(&p[b]))
            .unwrap_or(0);
        assert_eq!(peak, cycles * padded / count);
        assert!((p[peak] - 368.64).abs() < 0.01, "{}", p[peak]);
    }

    #[test]
    fn constant_controls_need_no_mode_and_stay_finite() {
        let spline = MuscleSpline::constant(15, 2.0, Interpolation::Linear, 0.3);
        let a = abstract_controls(&spline, &AbstractionSettings::default());
        assert!(a.controller.modes.is_empty());
        assert!((a.controller.mean[0] - 0.3).abs() < 1e-5);
        assert_eq!(a.controller.energy_fraction, 1.0);
        assert!(a.controller.is_valid());
    }
}
