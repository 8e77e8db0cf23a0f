//! The body stays whole: ten minutes of random use keep it finite, its springs
//! within bounds and its volume uninverted, and a tail fin folded over the last
//! ring springs back.

use glam::Vec3;

use crate::sim::body::body_layout::{REST_POSITIONS, TRIANGLES};
use crate::sim::body::swim_trials::LENGTH_M;
use crate::sim::body::{BodyCommand, FishBody, PectoralFins, SwimMc, SwimParams};
use crate::sim::common::fmath;

/// Signed volume enclosed by the surface triangles (positive = not inverted).
fn enclosed_volume(p: &[Vec3]) -> f32 {
    TRIANGLES
        .iter()
        .map(|[a, b, c]| p[*a].dot(p[*b].cross(p[*c])) / 6.0)
        .sum()
}

#[test]
fn long_random_run_stays_finite_and_intact() {
    // Ten simulated minutes; every 5 s a new speed, fin setting and current.
    let mut fish = FishBody::new(LENGTH_M, Vec3::ZERO, Vec3::X);
    let mut mc = SwimMc::default();
    let mut seed: u64 = 0x5EED_F15F;
    let mut random = move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 40) as f32 / (1u64 << 24) as f32
    };
    let rest_volume = enclosed_volume(&REST_POSITIONS);
    let mut command = BodyCommand::default();
    let mut params = SwimParams::MAX;
    let mut current = Vec3::ZERO;
    let steps = (600.0 / fish.dt_secs()) as usize;
    // (spine min, spine max, strain min, strain max), reported with --nocapture.
    let mut extremes = (f32::INFINITY, 0.0f32, f32::INFINITY, 0.0f32);
    for k in 0..steps {
        if k % 91 == 0 {
            params = mc.params_for_speed(random());
            params.anterior_frequency_hz *= 0.5 + random();
            params.posterior_frequency_hz = params.anterior_frequency_hz;
            command.fins = PectoralFins {
                left_angle_rad: 0.8 + 2.3 * random(),
                right_angle_rad: 0.8 + 2.3 * random(),
                ..PectoralFins::NEUTRAL
            };
            current = Vec3::new(random() - 0.5, random() - 0.5, random() - 0.5) * 0.2 * LENGTH_M;
        }
        command.muscle_contractions = mc.step(&params, fish.dt_secs());
        fish.step(&command, current);
        assert!(
            fish.positions_m().iter().all(|p| p.is_finite()),
            "NaN at step {k}"
        );
        assert_eq!(fish.clamped_pivots(), 0);
        let length = fish.spine_length_m() / LENGTH_M;
        assert!((0.9..=1.1).contains(&length), "length {length} at step {k}");
        let strains = fish.spring_strains();
        extremes = (
            extremes.0.min(length),
            extremes.1.max(length),
            strains.iter().fold(extremes.2, |a, s| a.min(*s)),
            strains.iter().fold(extremes.3, |a, s| a.max(*s)),
        );
        assert!(
            strains.iter().all(|s| (0.3..2.0).contains(s)),
            "step {k}: {strains:?}"
        );
        let volume = enclosed_volume(fish.positions_m()) / fmath::powi(LENGTH_M / 26.0, 3);
        assert!(
            volume > 0.5 * rest_volume,
            "collapsed: {volume} at step {k}"
        );
    }
    println!(
        "spine {:.3}..{:.3}, strains {:.2}..{:.2}",
        extremes.0, extremes.1, extremes.2, extremes.3
    );
}

#[test]
fn a_tail_fin_folded_over_the_last_ring_springs_back() {
    // The fin's tips mirrored through the plane of the last ring, to the front of
    // it: with the tips tied to that ring only, every spring kept its rest
    // length there and the fold was a second rest shape that fish fell into.
    use crate::sim::body::body_layout::{TAIL_FIN_NODES, ring_nodes};
    let mut fish = FishBody::new(LENGTH_M, Vec3::ZERO, Vec3::X);
    assert!(!fish.tail_fin_folded());
    let (positions, _) = fish.nodes_mut();
    let ring_x = ring_nodes(4).iter().map(|&i| positions[i].x).sum::<f32>() / 4.0;
    for i in TAIL_FIN_NODES {
        positions[i].x = 2.0 * ring_x - positions[i].x;
    }
    assert!(fish.tail_fin_folded());
    for _ in 0..(5.0 / fish.dt_secs()) as usize {
        fish.step(&BodyCommand::default(), Vec3::ZERO);
    }
    assert!(!fish.tail_fin_folded(), "still folded after 5 s");
    assert!(fish.positions_m().iter().all(|p| p.is_finite()));
}
