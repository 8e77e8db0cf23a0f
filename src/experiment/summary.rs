//! The results in one table: per level (or pair of levels) and measure, the
//! mean over seeds and its 95 % interval, for the dose–response plot.
//!
//! The interval is a percentile bootstrap of the mean: the seeds' values are
//! drawn again, with replacement, [`BOOTSTRAP_RESAMPLES`] times, and the
//! interval runs from the 2.5th to the 97.5th percentile of those means. Every
//! such mean lies between the smallest and the largest value measured, so the
//! interval never leaves what the measure can be (a polarization stays within
//! 0–1, a count is never negative). The t interval it replaces did: from three
//! seeds it gave polarization intervals like [−0.005, 0.42] and [0.60, 1.11].
//! With few seeds the bootstrap is rough (from three seeds it is about the
//! range of the three), so the window says on how many seeds each interval
//! rests and warns below [`FEW_SEEDS`].

use crate::sim::common::fmath;
use std::fmt::Write as _;

use serde_json::Value;

use crate::experiment::design::{Measure, Plan, Summary};
use crate::experiment::runner::RunResult;

/// One point of a dose–response curve (serialised for `shoal.experiment()`;
/// NaN, with one seed, becomes `null`).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct SummaryRow {
    /// The factor levels, in the design's order (empty without factors).
    pub levels: Vec<Value>,
    pub measure: Measure,
    /// `Mean` or `Final`: which per-run value was summarised (a series is
    /// summarised by its mean over the window).
    pub summary: Summary,
    /// Seeds completed at this level.
    pub n: usize,
    pub mean: f64,
    /// Sample standard deviation over seeds (NaN with one seed).
    pub sd: f64,
    /// The 95 % interval of the mean, a percentile bootstrap over the seeds
    /// (NaN with one seed; see the module's doc).
    pub ci95_low: f64,
    pub ci95_high: f64,
}

/// Resamples the interval is read from (4,000, chosen: two sets of 4,000
/// resamples of the same values put the 2.5th and 97.5th percentiles within
/// about 1 % of the values' spread of each other).
pub const BOOTSTRAP_RESAMPLES: usize = 4000;
/// Seeds below which an interval is called rough (5, chosen: from 3 seeds the
/// bootstrap interval is the range of the three).
pub const FEW_SEEDS: usize = 5;
/// The resampling's random numbers are fixed, so the same values always give
/// the same interval, in the browser as natively.
const BOOTSTRAP_SEED: u64 = 0x5EED_B007;

/// The mean of `values` (NaN for none), never outside their range: a sum of
/// equal values divided by their count can round a last bit past them, and a
/// mean printed beside its interval must not leave it.
pub fn mean_within(values: &[f64]) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    let mean = values.iter().sum::<f64>() / values.len() as f64;
    let min = values.iter().copied().fold(f64::INFINITY, f64::min);
    let max = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if min <= max && !mean.is_nan() {
        mean.clamp(min, max)
    } else {
        mean
    }
}

/// The 95 % percentile-bootstrap interval of the mean of `values` (NaN with
/// fewer than two values); always within [min, max] of the values.
pub fn bootstrap_interval(values: &[f64]) -> (f64, f64) {
    use rand::{Rng, SeedableRng};
    let n = values.len();
    if n < 2 {
        return (f64::NAN, f64::NAN);
    }
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(BOOTSTRAP_SEED);
    let mut means: Vec<f64> = (0..BOOTSTRAP_RESAMPLES)
        .map(|_| {
            // u32, not usize: the same draws on a 32-bit browser as natively.
            let sum: f64 = (0..n)
                .map(|_| values[rng.random_range(0..n as u32) as usize])
                .sum();
            sum / n as f64
        })
        .collect();
    means.sort_by(f64::total_cmp);
    // Within the values exactly (a mean of equal values can round a last bit
    // past them).
    let min = values.iter().copied().fold(f64::INFINITY, f64::min);
    let max = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (
        percentile(&means, 0.025).max(min).min(max),
        percentile(&means, 0.975).max(min).min(max),
    )
}

/// The `q` quantile of sorted `xs`, interpolated between neighbours.
fn percentile(xs: &[f64], q: f64) -> f64 {
    let at = q * (xs.len() - 1) as f64;
    let (below, share) = (at.floor() as usize, at - at.floor());
    let above = (below + 1).min(xs.len() - 1);
    xs[below] + share * (xs[above] - xs[below])
}

/// Per level combination (in run order) and measure (in the plan's order): the
/// mean and 95 % interval over the completed runs' seeds.
pub fn summarise(plan: &Plan, results: &[RunResult]) -> Vec<SummaryRow> {
    let mut sorted: Vec<&RunResult> = results.iter().collect();
    sorted.sort_by_key(|r| r.index);
    let mut groups: Vec<(Vec<Value>, Vec<&RunResult>)> = Vec::new();
    for r in sorted {
        match groups.last_mut() {
            Some((levels, runs)) if *levels == r.levels => runs.push(r),
            _ => groups.push((r.levels.clone(), vec![r])),
        }
    }
    let mut rows = Vec::new();
    for (levels, runs) in groups {
        for (m, &(measure, summary)) in plan.measures.iter().enumerate() {
            let values: Vec<f64> = runs
                .iter()
                .map(|r| match summary {
                    Summary::Final => r.last(m),
                    Summary::Mean | Summary::Series => r.mean(m),
                })
                .collect();
            let n = values.len();
            let mean = mean_within(&values);
            let sd = if n > 1 {
                (values
                    .iter()
                    .map(|v| fmath::powi_f64(v - mean, 2))
                    .sum::<f64>()
                    / (n - 1) as f64)
                    .sqrt()
            } else {
                f64::NAN
            };
            let (ci95_low, ci95_high) = bootstrap_interval(&values);
            rows.push(SummaryRow {
                levels: levels.clone(),
                measure,
                summary: if summary == Summary::Series {
                    Summary::Mean
                } else {
                    summary
                },
                n,
                mean,
                sd,
                ci95_low,
                ci95_high,
            });
        }
    }
    rows
}

/// The summary as a Markdown table (the command line prints it; the docs quote
/// it): one row per level, one column per measure, "mean [low, high]".
pub fn summary_table(plan: &Plan, rows: &[SummaryRow]) -> String {
    let mut out = String::new();
    let mut header: Vec<String> = plan.factors.iter().map(|f| f.key.clone()).collect();
    header.push("n".into());
    for &(measure, summary) in &plan.measures {
        let summary = if summary == Summary::Final {
            "final"
        } else {
            "mean"
        };
        header.push(format!("{} ({summary})", measure.name()));
    }
    let _ = writeln!(out, "| {} |", header.join(" | "));
    let _ = writeln!(
        out,
        "|{}",
        header.iter().map(|_| " ---: |").collect::<String>()
    );
    for chunk in rows.chunks(plan.measures.len().max(1)) {
        let Some(first) = chunk.first() else {
            continue;
        };
        let mut cells: Vec<String> = first.levels.iter().map(ToString::to_string).collect();
        cells.push(first.n.to_string());
        for row in chunk {
            cells.push(if row.ci95_low.is_finite() {
                format!(
                    "{} [{}, {}]",
                    significant(row.mean),
                    significant(row.ci95_low),
                    significant(row.ci95_high)
                )
            } else {
                significant(row.mean)
            });
        }
        let _ = writeln!(out, "| {} |", cells.join(" | "));
    }
    out
}

/// Three significant digits, for a table a person reads ("–" when not a
/// number).
pub fn significant(x: f64) -> String {
    if !x.is_finite() {
        return "–".into();
    }
    if x == 0.0 {
        return "0".into();
    }
    let digits = (2 - fmath::log10_f64(x.abs()).floor() as i32).clamp(0, 6) as usize;
    format!("{x:.digits$}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_interval_never_leaves_what_the_measure_can_be() {
        // Polarizations of three seeds near the top and near the bottom: the
        // t interval gave [0.60, 1.11] and [-0.005, 0.42] for such values.
        for values in [[0.62, 0.95, 0.99], [0.01, 0.02, 0.40], [0.0, 0.0, 3.0]] {
            let (low, high) = bootstrap_interval(&values);
            let (min, max) = (values[0], values[2]);
            assert!(
                min <= low && low <= high && high <= max,
                "{values:?}: [{low}, {high}]"
            );
            let mean = values.iter().sum::<f64>() / 3.0;
            assert!(low <= mean && mean <= high);
        }
        // One value: no interval; equal values: a point.
        assert!(bootstrap_interval(&[0.5]).0.is_nan());
        assert_eq!(bootstrap_interval(&[0.5, 0.5, 0.5]), (0.5, 0.5));
        // Three equal values whose plain mean rounds a last bit below them (a
        // class's three identical runs).
        let equal = [0.757_527_998_571_215_3; 3];
        assert!(equal.iter().sum::<f64>() / 3.0 < equal[0]);
        assert_eq!(mean_within(&equal), equal[0]);
        assert_eq!(bootstrap_interval(&equal), (equal[0], equal[0]));
        assert!(mean_within(&[]).is_nan());
        // The same values, the same interval (the browser's and the lab's).
        let values = [0.3, 0.5, 0.45, 0.7, 0.52, 0.61];
        assert_eq!(bootstrap_interval(&values), bootstrap_interval(&values));
    }

    #[test]
    fn with_more_seeds_the_interval_narrows_and_covers_the_true_mean() {
        // Seeds drawn from a known spread (uniform 0.4-0.8, mean 0.6): with 20
        // the interval is narrower than with 5, and over many such experiments
        // it holds the true mean about 95 % of the time (the percentile
        // bootstrap runs a little short with few seeds: at least 85 % at 10).
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let mut draw =
            |n: usize| -> Vec<f64> { (0..n).map(|_| 0.4 + 0.4 * rng.random::<f64>()).collect() };
        let width = |v: &[f64]| {
            let (lo, hi) = bootstrap_interval(v);
            hi - lo
        };
        let mut mean_width = |n: usize| (0..100).map(|_| width(&draw(n))).sum::<f64>() / 100.0;
        let (narrow, wide) = (mean_width(20), mean_width(5));
        assert!(narrow < wide, "20 seeds: {narrow}, 5 seeds: {wide}");
        let trials = 300;
        let covered = (0..trials)
            .filter(|_| {
                let (lo, hi) = bootstrap_interval(&draw(10));
                lo <= 0.6 && 0.6 <= hi
            })
            .count();
        let share = covered as f64 / trials as f64;
        assert!((0.85..=0.99).contains(&share), "covered {share}");
    }
}
