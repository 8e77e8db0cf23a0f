//! The school's numbers over time, for live plots, `shoal.state().metrics` and the
//! CSV export.
//!
//! The world computes its metrics every step (`sim::school_metrics`); the history
//! keeps one sample every [`SAMPLE_EVERY_STEPS`] steps for the last
//! [`HISTORY_SECS`] simulated seconds.

use std::collections::VecDeque;

use serde::Serialize;

use crate::sim::SchoolMetrics;

/// Steps between two samples. Default 15 (a quarter of a simulated second): smooth
/// plots, and five minutes fit in 1,200 samples.
pub const SAMPLE_EVERY_STEPS: u64 = crate::sim::scene::BOID_SAMPLE_EVERY_STEPS;

/// How much simulated time the history keeps, in seconds. Default 300 s: "the last
/// minutes" of a lesson, long enough to see a school form and break.
pub const HISTORY_SECS: f64 = 300.0;

/// How often each of the five forces acted, as fractions of fish-steps.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct ForceShares {
    pub containment: f64,
    pub alignment: f64,
    pub cohesion: f64,
    pub separation: f64,
    pub avoidance: f64,
}

impl ForceShares {
    pub fn from_array(a: [f64; 5]) -> Self {
        Self {
            containment: a[0],
            alignment: a[1],
            cohesion: a[2],
            separation: a[3],
            avoidance: a[4],
        }
    }

    pub fn to_array(self) -> [f64; 5] {
        [
            self.containment,
            self.alignment,
            self.cohesion,
            self.separation,
            self.avoidance,
        ]
    }
}

/// One instant's metrics, as `shoal.state().metrics` reports them and as a CSV row.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct MetricsSample {
    pub time_secs: f64,
    /// ‖Σ v̂‖/N: 1 when all fish swim the same way.
    pub polarization: f32,
    /// Normalised angular momentum about the group centre: 1 for a perfect mill.
    pub milling: f32,
    /// Mean nearest-neighbour distance in body lengths.
    pub nnd_body_lengths: f32,
    /// Clusters of fish linked by gaps of at most two body lengths.
    pub groups: u32,
    /// Mean speed in m/s.
    pub mean_speed: f32,
    /// Fraction of fish-steps on which each force was applied (the lottery of the
    /// random control modes shows here).
    pub force_frequencies: ForceShares,
    /// Fish caught by sharks since the start.
    pub catches: u64,
}

impl MetricsSample {
    pub fn new(
        time_secs: f64,
        metrics: &SchoolMetrics,
        force_frequencies: [f64; 5],
        catches: u64,
    ) -> Self {
        Self {
            time_secs,
            polarization: metrics.polarization,
            milling: metrics.milling,
            nnd_body_lengths: metrics.nnd_body_lengths,
            groups: metrics.groups,
            mean_speed: metrics.mean_speed_m_per_s,
            force_frequencies: ForceShares::from_array(force_frequencies),
            catches,
        }
    }
}

/// The recent samples, oldest first.
#[derive(Clone, Debug, Default)]
pub struct MetricsHistory {
    samples: VecDeque<MetricsSample>,
}

impl MetricsHistory {
    /// Adds a sample and forgets those older than [`HISTORY_SECS`].
    pub fn push(&mut self, sample: MetricsSample) {
        self.samples.push_back(sample);
        while self
            .samples
            .front()
            .is_some_and(|first| sample.time_secs - first.time_secs > HISTORY_SECS)
        {
            self.samples.pop_front();
        }
    }

    pub fn clear(&mut self) {
        self.samples.clear();
    }

    pub fn samples(&self) -> impl ExactSizeIterator<Item = &MetricsSample> + Clone {
        self.samples.iter()
    }

    pub fn latest(&self) -> Option<&MetricsSample> {
        self.samples.back()
    }

    pub fn len(&self) -> usize {
        self.samples.len()
    }

    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }

    /// The history as CSV (a header line, then one line per sample), ready for a
    /// spreadsheet. `tank` names the tank in the first column.
    pub fn to_csv(&self, tank: &str, out: &mut String) {
        use std::fmt::Write as _;
        for s in &self.samples {
            let f = s.force_frequencies;
            // Writing to a String cannot fail.
            let _ = writeln!(
                out,
                "{tank},{:.3},{:.4},{:.4},{:.3},{},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{}",
                s.time_secs,
                s.polarization,
                s.milling,
                s.nnd_body_lengths,
                s.groups,
                s.mean_speed,
                f.containment,
                f.alignment,
                f.cohesion,
                f.separation,
                f.avoidance,
                s.catches
            );
        }
    }
}

/// The header line matching [`MetricsHistory::to_csv`].
pub const CSV_HEADER: &str = "tank,time_s,polarization,milling,nnd_body_lengths,groups,mean_speed_m_per_s,\
containment_share,alignment_share,cohesion_share,separation_share,avoidance_share,catches\n";

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(t: f64) -> MetricsSample {
        MetricsSample {
            time_secs: t,
            polarization: 0.5,
            groups: 2,
            ..MetricsSample::default()
        }
    }

    #[test]
    fn the_history_keeps_the_last_five_minutes() {
        let mut history = MetricsHistory::default();
        for i in 0..2000 {
            history.push(sample(f64::from(i) * 0.25));
        }
        let first = history.samples().next().unwrap().time_secs;
        let last = history.latest().unwrap().time_secs;
        assert!(
            (last - first - HISTORY_SECS).abs() < 0.26,
            "{first}..{last}"
        );
    }

    #[test]
    fn csv_has_a_header_and_one_row_per_sample_with_every_column() {
        let mut history = MetricsHistory::default();
        history.push(sample(0.0));
        history.push(sample(0.25));
        let mut csv = CSV_HEADER.to_owned();
        history.to_csv("left", &mut csv);
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 3);
        let columns = lines[0].split(',').count();
        assert!(lines.iter().all(|l| l.split(',').count() == columns));
        assert!(lines[2].starts_with("left,0.250,0.5000,"), "{}", lines[2]);
    }
}
