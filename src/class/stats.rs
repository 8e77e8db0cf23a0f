//! The dashboard's numbers: the prediction histogram and the pooled result.
//!
//! The pooled result puts every student's measured value of a measure (each
//! student's tank runs its own seed: class seed + join order) into one
//! distribution, with its mean and 95 % interval. The interval is the
//! experiment window's percentile bootstrap of the mean
//! ([`crate::experiment::summary::bootstrap_interval`]): it always lies
//! between the smallest and largest value measured, so it never leaves what
//! the measure can be (a count is never negative, a polarization stays in
//! 0–1).

use std::collections::BTreeMap;

use serde::Serialize;

use super::view::StudentRecord;

/// The histogram's bars, most chosen first (ties in the answers' order).
pub fn histogram_bars(histogram: &BTreeMap<String, u64>) -> Vec<(String, u64)> {
    let mut bars: Vec<(String, u64)> = histogram
        .iter()
        .filter(|(_, n)| **n > 0)
        .map(|(k, n)| (k.clone(), *n))
        .collect();
    bars.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
    bars
}

/// One measure pooled over the class.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Pooled {
    pub measure: String,
    /// Values pooled (one per run reported).
    pub n: usize,
    /// Students who reported one.
    pub students: usize,
    pub mean: f64,
    /// The 95 % interval of the mean (NaN with one value).
    pub low: f64,
    pub high: f64,
    pub min: f64,
    pub max: f64,
    /// Every value, in join order (for the dot plot).
    pub values: Vec<f64>,
}

/// Every measure reported by the class, in name order, pooled.
pub fn pooled(roster: &[StudentRecord]) -> Vec<Pooled> {
    let mut by_measure: BTreeMap<&str, (Vec<f64>, Vec<i64>)> = BTreeMap::new();
    let mut order: Vec<&StudentRecord> = roster.iter().collect();
    order.sort_by_key(|s| s.join_order);
    for student in order {
        for row in &student.results {
            if !row.value.is_finite() {
                continue;
            }
            let entry = by_measure.entry(&row.measure).or_default();
            entry.0.push(row.value);
            if !entry.1.contains(&student.join_order) {
                entry.1.push(student.join_order);
            }
        }
    }
    by_measure
        .into_iter()
        .map(|(measure, (values, students))| {
            let n = values.len();
            let mean = crate::experiment::summary::mean_within(&values);
            let (low, high) = crate::experiment::summary::bootstrap_interval(&values);
            Pooled {
                measure: measure.to_owned(),
                n,
                students: students.len(),
                mean,
                low,
                high,
                min: values.iter().copied().fold(f64::INFINITY, f64::min),
                max: values.iter().copied().fold(f64::NEG_INFINITY, f64::max),
                values,
            }
        })
        .collect()
}

/// How many students are at each step (look, predict, run, explain), and how
/// many have not said yet.
pub fn step_counts(roster: &[StudentRecord]) -> ([usize; 4], usize) {
    let mut counts = [0; 4];
    let mut none = 0;
    for s in roster {
        match s.step.as_deref().and_then(super::step_index) {
            Some(k) => counts[k] += 1,
            None => none += 1,
        }
    }
    (counts, none)
}
