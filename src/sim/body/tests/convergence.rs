//! What the tables say is the model, not the integrator: a lagged Jacobian and a
//! doubled time resolution barely change the swimming and the key turns.

use glam::Vec3;

use super::{swim, swim_from};
use crate::sim::body::swim_trials::{LENGTH_M, resolution_row};
use crate::sim::body::{BodyParams, ControlSampling, FishBody, PectoralFins, SwimParams};

#[test]
fn a_lagged_jacobian_swims_nearly_like_the_exact_one() {
    // `BodyParams::jacobian_interval` = 2: one factorisation per two substeps.
    let lagged = FishBody::with_params(
        LENGTH_M,
        Vec3::ZERO,
        Vec3::X,
        BodyParams {
            jacobian_interval: 2,
            ..Default::default()
        },
    );
    let secs = 20.0;
    let (exact, h0) = swim(SwimParams::MAX, PectoralFins::NEUTRAL, secs);
    let (lagged, h1) = swim_from(lagged, SwimParams::MAX, PectoralFins::NEUTRAL, secs);
    assert!(lagged.positions_m().iter().all(|p| p.is_finite()));
    let v0 = (exact.centre_of_mass_m() - h0).x;
    let v1 = (lagged.centre_of_mass_m() - h1).x;
    assert!((v1 / v0 - 1.0).abs() < 0.05, "lagged {v1} exact {v0}");
    assert!(lagged.up().z > 0.95, "not upright: {}", lagged.up());
}

/// The default body at twice its time resolution: twice the substeps (so the
/// controllers are sampled twice as often too), the matrix refreshed as often in
/// time.
fn doubled(body: BodyParams) -> BodyParams {
    BodyParams {
        substeps: 2 * body.substeps,
        jacobian_interval: 2 * body.jacobian_interval,
        ..body
    }
}

#[test]
fn the_default_body_is_converged() {
    // Doubling the time resolution changes the top speed and every key turn by
    // less than 3 %: what the tables say is the model, not the integrator.
    let body = BodyParams::default();
    let sampling = ControlSampling::default();
    let (top, turns) = resolution_row(body, sampling);
    let (top2, turns2) = resolution_row(doubled(body), sampling);
    let change = |a: f32, b: f32| (b / a - 1.0).abs();
    assert!(change(top, top2) < 0.03, "top speed {top} → {top2} BL/s");
    for (k, (a, b)) in turns.into_iter().zip(turns2).enumerate() {
        assert!(change(a, b) < 0.03, "key turn {k}: {a}° → {b}°");
    }
    // The bridge's top speed is the body's.
    let bridge = crate::sim::body::motor_bridge::TOP_SPEED_BODY_LENGTHS_PER_SEC;
    assert!(
        change(bridge, top) < 0.03,
        "bridge {bridge}, body {top} BL/s"
    );
}
