//! What the world measures after every step, for the lab's charts: the school's
//! order parameters ([`SchoolMetrics`]; the nearest-neighbour distance and the
//! groups four times a second, see [`SPATIAL_METRICS_EVERY_STEPS`]), how often each SIMBA force was applied
//! (the control modes' lottery made visible), and the sharks' catches.

use serde::Serialize;

use crate::sim::common::fish::Fish;
use crate::sim::common::school_metrics::{self, SchoolMeter, SchoolMetrics};
use crate::sim::common::tank::Tank;

/// Steps between two measurements of the nearest-neighbour distance, the
/// number of groups and milling (about each group's centre). Default 15 (four times a second): the plots and the CSV
/// take a sample every 15 steps (`metrics_history::SAMPLE_EVERY_STEPS`), so
/// each sample holds a fresh measurement; both change over seconds, and
/// measuring them costs 30 times the other metrics (8 ms with 20,000 fish).
/// Polarization and mean speed are measured after every step.
pub const SPATIAL_METRICS_EVERY_STEPS: u64 = 15;

/// Steps in the "recent" window of force frequencies. Default 60 steps = 1 s at
/// [`crate::sim::DT_SECS`]: long enough to average a random mode's lottery over a
/// school (200 fish × 60 steps = 12,000 draws, about ±0.5 %), short enough to
/// follow a slider within a second.
pub const FORCE_WINDOW_STEPS: usize = 60;

/// The world's measurements after a step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct WorldMetrics {
    /// Polarization, milling, nearest-neighbour distance, groups and mean speed
    /// of the fish.
    pub school: SchoolMetrics,
    /// Fraction of fish-steps on which each force (in
    /// [`crate::sim::boids::control_mode::Force::ALL`] order) was applied over the last
    /// [`FORCE_WINDOW_STEPS`] boid steps.
    pub force_frequencies_recent: [f64; 5],
    /// The same since the start (or the last reset).
    pub force_frequencies_total: [f64; 5],
    /// Fish caught by sharks since the start (or the last reset).
    pub catches: u64,
}

/// Counts of applied forces: a ring of the last [`FORCE_WINDOW_STEPS`] steps and
/// running totals. Pushing a step is O(1).
#[derive(Clone, Debug)]
pub struct ForceWindow {
    ring: [([u32; 5], u32); FORCE_WINDOW_STEPS],
    next: usize,
    recent_counts: [u64; 5],
    recent_fish_steps: u64,
    total_counts: [u64; 5],
    total_fish_steps: u64,
}

impl Default for ForceWindow {
    fn default() -> Self {
        Self {
            ring: [([0; 5], 0); FORCE_WINDOW_STEPS],
            next: 0,
            recent_counts: [0; 5],
            recent_fish_steps: 0,
            total_counts: [0; 5],
            total_fish_steps: 0,
        }
    }
}

impl ForceWindow {
    /// Records one step: how many fish applied each force, out of `fish_steps`.
    pub fn push(&mut self, applied: [u32; 5], fish_steps: u32) {
        let (old_applied, old_fish_steps) = self.ring[self.next];
        for i in 0..5 {
            self.recent_counts[i] =
                self.recent_counts[i] + u64::from(applied[i]) - u64::from(old_applied[i]);
            self.total_counts[i] += u64::from(applied[i]);
        }
        self.recent_fish_steps =
            self.recent_fish_steps + u64::from(fish_steps) - u64::from(old_fish_steps);
        self.total_fish_steps += u64::from(fish_steps);
        self.ring[self.next] = (applied, fish_steps);
        self.next = (self.next + 1) % FORCE_WINDOW_STEPS;
    }

    /// Frequencies over the last [`FORCE_WINDOW_STEPS`] steps (zeros before any).
    pub fn recent(&self) -> [f64; 5] {
        let n = self.recent_fish_steps.max(1) as f64;
        std::array::from_fn(|i| self.recent_counts[i] as f64 / n)
    }

    /// Frequencies since the start (zeros before any step).
    pub fn total(&self) -> [f64; 5] {
        let n = self.total_fish_steps.max(1) as f64;
        std::array::from_fn(|i| self.total_counts[i] as f64 / n)
    }
}

/// The metrics stage of the world's step: measures the school after every step
/// and keeps the result with the force frequencies and catches.
#[derive(Clone, Debug, Default)]
pub(super) struct WorldMeter {
    meter: SchoolMeter,
    metrics: WorldMetrics,
}

impl WorldMeter {
    /// Measures `fish` in `tank` after step number `steps`: polarization,
    /// milling and mean speed every time; the nearest-neighbour distance and
    /// the groups every [`SPATIAL_METRICS_EVERY_STEPS`] steps (and at the
    /// start), kept in between. `forces` are the control modes' counts,
    /// `catches` the sharks'.
    pub(super) fn measure(
        &mut self,
        steps: u64,
        fish: &[Fish],
        tank: &Tank,
        forces: &ForceWindow,
        catches: u64,
    ) {
        let school = if steps.is_multiple_of(SPATIAL_METRICS_EVERY_STEPS) {
            self.meter.measure(fish, tank.min_m, tank.max_m)
        } else {
            SchoolMetrics {
                nnd_body_lengths: self.metrics.school.nnd_body_lengths,
                groups: self.metrics.school.groups,
                milling: self.metrics.school.milling,
                ..school_metrics::order_parameters(fish)
            }
        };
        self.metrics = WorldMetrics {
            school,
            force_frequencies_recent: forces.recent(),
            force_frequencies_total: forces.total(),
            catches,
        };
    }

    /// The last measurement.
    pub(super) fn metrics(&self) -> &WorldMetrics {
        &self.metrics
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::boids::metrics::*;

    #[test]
    fn the_recent_window_forgets_steps_older_than_a_second() {
        let mut w = ForceWindow::default();
        for _ in 0..FORCE_WINDOW_STEPS {
            w.push([10, 0, 0, 0, 0], 10);
        }
        assert_eq!(w.recent()[0], 1.0);
        for _ in 0..FORCE_WINDOW_STEPS {
            w.push([0, 5, 0, 0, 0], 10);
        }
        assert_eq!(w.recent(), [0.0, 0.5, 0.0, 0.0, 0.0]);
        assert_eq!(w.total(), [0.5, 0.25, 0.0, 0.0, 0.0]);
    }
}
