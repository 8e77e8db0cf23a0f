//! The results in one table: per level (or pair of levels) and measure, the
//! mean over seeds and its 95 % confidence interval, for the dose–response plot.
//!
//! The interval is the mean ± t(0.975, n − 1) · s / √n, with s the sample
//! standard deviation over the n seeds: the seeds are independent replicates,
//! and n is small (3 to 10), so the t distribution, not the normal one.

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
    /// The 95 % confidence interval of the mean (NaN with one seed).
    pub ci95_low: f64,
    pub ci95_high: f64,
}

/// Two-sided 95 % quantile of Student's t with `df` degrees of freedom
/// (t(0.975, df)): a table to 30, the Cornish–Fisher expansion beyond (error
/// under 1e-4).
pub fn t_975(df: usize) -> f64 {
    const TABLE: [f64; 30] = [
        12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160,
        2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056,
        2.052, 2.048, 2.045, 2.042,
    ];
    match df {
        0 => f64::NAN,
        1..=30 => TABLE[df - 1],
        _ => {
            let z: f64 = 1.959_963_985;
            let v = df as f64;
            z + (fmath::powi_f64(z, 3) + z) / (4.0 * v)
                + (5.0 * fmath::powi_f64(z, 5) + 16.0 * fmath::powi_f64(z, 3) + 3.0 * z)
                    / (96.0 * v * v)
                + (3.0 * fmath::powi_f64(z, 7)
                    + 19.0 * fmath::powi_f64(z, 5)
                    + 17.0 * fmath::powi_f64(z, 3)
                    - 15.0 * z)
                    / (384.0 * fmath::powi_f64(v, 3))
        }
    }
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
            let mean = values.iter().sum::<f64>() / n as f64;
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
            let half = t_975(n.saturating_sub(1)) * sd / (n as f64).sqrt();
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
                ci95_low: mean - half,
                ci95_high: mean + half,
            });
        }
    }
    rows
}

/// The summary as a Markdown table (the command line prints it; the docs quote
/// it): one row per level, one column per measure, "mean ± half-width".
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
            cells.push(if row.sd.is_finite() {
                format!(
                    "{} ± {}",
                    significant(row.mean),
                    significant(row.ci95_high - row.mean)
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
    fn the_t_quantile_meets_its_table_and_the_normal_limit() {
        assert_eq!(t_975(1), 12.706);
        assert_eq!(t_975(4), 2.776);
        // Past the table: 2.0395 at 31, 2.0211 at 40, 1.9840 at 100 (tables).
        assert!((t_975(31) - 2.0395).abs() < 2e-4, "{}", t_975(31));
        assert!((t_975(40) - 2.0211).abs() < 2e-4, "{}", t_975(40));
        assert!((t_975(100) - 1.9840).abs() < 2e-4, "{}", t_975(100));
        assert!(t_975(0).is_nan());
    }
}
