//! The metrics stage: the school is measured after every step, the spatial
//! measures every few steps.

use super::boid_world;
use crate::sim::boids::world::BoidParams;

#[test]
fn metrics_are_measured_after_every_step() {
    let mut w = boid_world(BoidParams::group(), 300);
    for _ in 0..90 {
        w.step();
    }
    // Step 90 is a multiple of SPATIAL_METRICS_EVERY_STEPS: all fresh.
    let fresh =
        crate::sim::common::school_metrics::measure(w.fish(), w.tank().min_m, w.tank().max_m);
    assert_eq!(w.metrics().school, fresh);
    // Blended mode applies every weighted force on every fish-step.
    assert_eq!(w.metrics().force_frequencies_recent, [1.0; 5]);
    assert_eq!(w.metrics().force_frequencies_total, w.force_frequencies());
    // One step later the order parameters are new, the spatial ones kept.
    w.step();
    let order = crate::sim::common::school_metrics::order_parameters(w.fish());
    let school = w.metrics().school;
    assert_eq!(school.polarization, order.polarization);
    assert_eq!(school.mean_speed_m_per_s, order.mean_speed_m_per_s);
    assert_eq!(
        (school.groups, school.nnd_body_lengths),
        (fresh.groups, fresh.nnd_body_lengths)
    );
}
