//! The control modes in the world: the group weights school in every mode,
//! and Monte Carlo applies each urge as often as its weight says.

use super::{boid_world, measure_minute};
use crate::sim::boids::control_mode::{self, ControlMode};
use crate::sim::boids::world::BoidParams;

#[test]
fn the_group_weights_school_in_direct_alternate_mode_too() {
    let m = measure_minute(
        BoidParams {
            mode: ControlMode::DirectAlternate,
            ..BoidParams::group()
        },
        &[1, 2],
    );
    assert!(m.polarization > 0.7 && m.groups <= 2.0, "{m:?}");
}

#[test]
fn the_group_weights_school_in_classic_mode_at_a_real_swimming_speed() {
    // One action per step (the steering paper ran Table 1 this way): the
    // group weights still make one polarized school, swimming well above the
    // minimum speed, and the individual weights still do not. Six seeds: one
    // seed's polarization ranges from 0.50 to 0.89 (seeds 1-6: 0.76, 0.50,
    // 0.89, 0.66, 0.83, 0.83), so two seeds were too few to say it (their
    // mean was 0.63 once the simulation's sin and cos became libm's).
    let classic = |params: BoidParams| BoidParams {
        mode: ControlMode::Classic,
        ..params
    };
    let seeds = [1, 2, 3, 4, 5, 6];
    let g = measure_minute(classic(BoidParams::group()), &seeds);
    let i = measure_minute(classic(BoidParams::individual()), &seeds);
    let min_speed = boid_world(BoidParams::group(), 1)
        .params()
        .min_speed_m_per_s;
    assert!(g.polarization > 0.7 && g.groups <= 2.0, "group {g:?}");
    assert!(
        g.speed_m_per_s > 2.0 * min_speed,
        "group {g:?}, minimum {min_speed}"
    );
    assert!(i.polarization < 0.45, "individual {i:?}");
    assert!(
        i.nnd_body_lengths >= 1.5 * g.nnd_body_lengths,
        "individual {i:?} vs group {g:?}"
    );
}

#[test]
fn the_monte_carlo_paper_preset_forms_a_group_that_keeps_off_the_rocks() {
    let params = BoidParams {
        weights: control_mode::MONTE_CARLO_PAPER_WEIGHTS.map(|w| w * 100.0 / 3.2),
        mode: ControlMode::MonteCarlo,
        ..BoidParams::group()
    };
    let seeds = [1, 2];
    let m = measure_minute(params, &seeds);
    assert!(m.groups <= 2.0 && m.polarization > 0.6, "{m:?}");
    // Fish-steps within 0.1 m of a rock: a few brushes at most.
    assert!(m.at_rock < 0.005, "{m:?}");
}

// Each slider's effect has the sign of its name: runs that differ in one
// weight only (from the Group preset), seeds 1 and 2.

#[test]
fn monte_carlo_in_the_world_applies_forces_as_often_as_their_weights_say() {
    let params = BoidParams {
        mode: ControlMode::MonteCarlo,
        weights: control_mode::MONTE_CARLO_PAPER_WEIGHTS,
        ..BoidParams::group()
    };
    let mut w = boid_world(params, 200);
    for _ in 0..600 {
        w.step();
    }
    let total: f32 = control_mode::MONTE_CARLO_PAPER_WEIGHTS.iter().sum();
    for (i, seen) in w.force_frequencies().into_iter().enumerate() {
        let expected = f64::from(control_mode::MONTE_CARLO_PAPER_WEIGHTS[i] / total);
        assert!(
            (seen - expected).abs() < 0.01,
            "force {i}: {seen} vs {expected}"
        );
    }
}
