//! The swim-MC swims the body forward, roughly straight, at a speed that grows
//! with amplitude and frequency and that the bridge's speed curve predicts; without
//! input the body comes to rest.

use glam::Vec3;

use super::swim;
use crate::sim::body::physical_fish::trials::straight_speed_at_amplitude;
use crate::sim::body::swim_trials::{LENGTH_M, speed_bl_per_s, with};
use crate::sim::body::{BodyCommand, FishBody, PectoralFins, SwimParams};
use crate::sim::common::fmath;

/// Least-squares line through (x, y): (slope, r²).
fn fit_line(points: &[(f32, f32)]) -> (f32, f32) {
    let n = points.len() as f32;
    let mx = points.iter().map(|p| p.0).sum::<f32>() / n;
    let my = points.iter().map(|p| p.1).sum::<f32>() / n;
    let sxy: f32 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f32 = points.iter().map(|p| fmath::powi(p.0 - mx, 2)).sum();
    let syy: f32 = points.iter().map(|p| fmath::powi(p.1 - my, 2)).sum();
    let slope = if sxx > 0.0 { sxy / sxx } else { 0.0 };
    let r2 = if sxx > 0.0 && syy > 0.0 {
        sxy * sxy / (sxx * syy)
    } else {
        0.0
    };
    (slope, r2)
}

#[test]
fn swim_mc_swims_forward_roughly_straight() {
    let (fish, half) = swim(SwimParams::MAX, PectoralFins::NEUTRAL, 60.0);
    let d = fish.centre_of_mass_m() - half;
    // Real fish and the paper's demos cruise at 0.5–1 body lengths/s.
    let speed_bl_per_s = d.x / 30.0 / LENGTH_M;
    assert!(
        speed_bl_per_s > 0.5,
        "top speed too low: {speed_bl_per_s} BL/s"
    );
    let heading_deg = fmath::atan2(d.y, d.x).to_degrees();
    assert!(heading_deg.abs() < 10.0, "veers {heading_deg}°");
    assert!(d.z.abs() < 0.1 * d.x, "climbs or sinks: {d}");
    assert!(fish.up().z > 0.95, "not upright: {}", fish.up());
}

#[test]
fn speed_grows_linearly_with_amplitude() {
    let points: Vec<(f32, f32)> = [0.25, 0.5, 0.75, 1.0]
        .into_iter()
        .map(|r| (r, speed_bl_per_s(with(r, 3.0))))
        .collect();
    let (slope, r2) = fit_line(&points);
    assert!(slope > 0.0 && r2 > 0.9, "slope {slope} r² {r2} {points:?}");
}

#[test]
fn speed_grows_with_frequency_below_saturation() {
    let points: Vec<(f32, f32)> = [0.5, 1.0, 1.5, 2.0, 2.5]
        .into_iter()
        .map(|f| (f, speed_bl_per_s(with(1.0, f))))
        .collect();
    let (slope, r2) = fit_line(&points);
    assert!(slope > 0.0 && r2 > 0.9, "slope {slope} r² {r2} {points:?}");
}

#[test]
fn without_muscle_input_the_fish_comes_to_rest_without_drift_or_spin() {
    // At rest it stays put.
    let (still, _) = swim(with(0.0, 0.0), PectoralFins::NEUTRAL, 30.0);
    let start = FishBody::new(LENGTH_M, Vec3::ZERO, Vec3::X);
    assert!(still.centre_of_mass_m().length() < 1e-3 * LENGTH_M);
    assert!(still.forward().dot(start.forward()) > 0.9999);
    // Launched, it glides to a stop along its heading.
    let mut fish = FishBody::new(LENGTH_M, Vec3::ZERO, Vec3::X);
    fish.set_uniform_velocity_m_per_s(Vec3::X * 0.5 * LENGTH_M);
    let e0 = fish.kinetic_energy();
    for _ in 0..(120.0 / fish.dt_secs()) as usize {
        fish.step(&BodyCommand::default(), Vec3::ZERO);
    }
    assert!(fish.kinetic_energy() < 1e-3 * e0);
    let c = fish.centre_of_mass_m();
    assert!(
        c.y.abs() < 1e-3 * LENGTH_M && c.z.abs() < 1e-3 * LENGTH_M,
        "{c}"
    );
    assert!(fish.forward().dot(Vec3::X) > 0.9999, "{}", fish.forward());
}

#[test]
fn the_swim_mc_delivers_the_speed_asked_for() {
    // swim-MC(speed) reads the amplitude off the measured speed curve; if the
    // body changes and the curve is not re-measured, this fails.
    let full = straight_speed_at_amplitude(1.0);
    let top = 0.5 * crate::sim::body::motor_bridge::TOP_SPEED_BODY_LENGTHS_PER_SEC;
    assert!(
        (full - top).abs() < 0.03 * top,
        "full {full} m/s, top {top}"
    );
    for k in [0.2, 0.35, 0.5, 0.7, 0.9] {
        let a = crate::sim::body::amplitude_for_speed(k);
        let got = straight_speed_at_amplitude(a) / full;
        assert!(
            (got - k).abs() < 0.02,
            "asked {k}, swam {got} of full speed"
        );
    }
}
