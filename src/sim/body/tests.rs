//! Behavioural specifications of the fish body (Tu & Terzopoulos 1994 §3): it swims
//! under the swim-MC, speed follows amplitude and frequency, it rests without input,
//! it survives long random use, its pectoral fins pitch and brake, and the turn-MC
//! turns it by the angle asked for, to either side.
//! All runs are deterministic (fixed seeds, fixed step).

use crate::sim::common::fmath;
use glam::Vec3;

use crate::sim::body::body_layout::{REST_POSITIONS, TRIANGLES};
use crate::sim::body::{
    BodyCommand, BodyParams, ControlSampling, FishBody, Integrator, PectoralFins, SwimMc,
    SwimParams,
};

/// Length of the test fish in metres: the paper's 26 units, so numbers read as paper
/// units.
const LENGTH_M: f32 = 26.0;

/// Swims for `secs` with fixed parameters and fins; returns the fish and its centre
/// of mass at the half-way time.
fn swim(params: SwimParams, fins: PectoralFins, secs: f32) -> (FishBody, Vec3) {
    swim_from(
        FishBody::new(LENGTH_M, Vec3::ZERO, Vec3::X),
        params,
        fins,
        secs,
    )
}

/// As [`swim`] from a given fish, the controller sampled at every substep.
fn swim_from(
    fish: FishBody,
    params: SwimParams,
    fins: PectoralFins,
    secs: f32,
) -> (FishBody, Vec3) {
    swim_sampled(fish, params, fins, secs, ControlSampling::default())
}

/// As [`swim_from`] with the controller sampled as `sampling` says.
fn swim_sampled(
    mut fish: FishBody,
    params: SwimParams,
    fins: PectoralFins,
    secs: f32,
    sampling: ControlSampling,
) -> (FishBody, Vec3) {
    let mut mc = SwimMc::default();
    let dt = fish.dt_secs();
    let steps = (secs / dt) as usize;
    let mut half = Vec3::ZERO;
    for k in 0..steps {
        match sampling {
            ControlSampling::PerStep => fish.step(
                &BodyCommand {
                    muscle_contractions: mc.muscles_at(&params, dt),
                    fins,
                },
                Vec3::ZERO,
            ),
            ControlSampling::PerSubstep => {
                fish.step_with(&fins, Vec3::ZERO, |t| mc.muscles_at(&params, t));
            }
        }
        mc.advance(&params, dt);
        if k + 1 == steps / 2 {
            half = fish.centre_of_mass_m();
        }
    }
    (fish, half)
}

/// Mean forward speed over the second half of a 60 s run, body lengths per second.
fn speed_bl_per_s(params: SwimParams) -> f32 {
    speed_with(params, BodyParams::default(), ControlSampling::default())
}

/// [`speed_bl_per_s`] on a body with `body` parameters, the controller sampled as
/// `sampling` says.
fn speed_with(params: SwimParams, body: BodyParams, sampling: ControlSampling) -> f32 {
    let fish = FishBody::with_params(LENGTH_M, Vec3::ZERO, Vec3::X, body);
    let (fish, half) = swim_sampled(fish, params, PectoralFins::NEUTRAL, 60.0, sampling);
    (fish.centre_of_mass_m() - half).x / 30.0 / LENGTH_M
}

fn with(amplitude: f32, frequency_hz: f32) -> SwimParams {
    SwimParams {
        anterior_amplitude: amplitude,
        anterior_frequency_hz: frequency_hz,
        posterior_amplitude: amplitude,
        posterior_frequency_hz: frequency_hz,
    }
}

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

/// Signed volume enclosed by the surface triangles (positive = not inverted).
fn enclosed_volume(p: &[Vec3]) -> f32 {
    TRIANGLES
        .iter()
        .map(|[a, b, c]| p[*a].dot(p[*b].cross(p[*c])) / 6.0)
        .sum()
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

#[test]
fn pectoral_fin_pitch_makes_the_fish_ascend_or_descend() {
    let (level, h0) = swim(SwimParams::MAX, PectoralFins::NEUTRAL, 60.0);
    let (up, h1) = swim(SwimParams::MAX, PectoralFins::pitch(0.5), 60.0);
    let (down, h2) = swim(SwimParams::MAX, PectoralFins::pitch(-0.5), 60.0);
    let climb = |f: &FishBody, h: Vec3| (f.centre_of_mass_m() - h).z;
    let (dz0, dz1, dz2) = (climb(&level, h0), climb(&up, h1), climb(&down, h2));
    assert!(dz1 > dz0 + 0.005 * LENGTH_M, "no ascent: {dz1} vs {dz0}");
    assert!(dz2 < dz0 - 0.005 * LENGTH_M, "no descent: {dz2} vs {dz0}");
}

#[test]
fn the_fin_trim_pitches_the_body_and_climbs_faster_than_lift_alone() {
    // The cause: the same fin angles (0.3 rad up), trimming or not. Lift alone
    // climbs about 1 cm/s with the body level; the trimmed body pitches nose up
    // by about the fins' pitch and swims up its own axis.
    let secs = 20.0;
    let (lift, h0) = swim(SwimParams::MAX, PectoralFins::pitch(0.3), secs);
    let (trim, h1) = swim(SwimParams::MAX, PectoralFins::climb(0.3), secs);
    let (dive, h2) = swim(SwimParams::MAX, PectoralFins::climb(-0.3), secs);
    let climb = |f: &FishBody, h: Vec3| (f.centre_of_mass_m() - h).z / secs;
    let (c0, c1, c2) = (climb(&lift, h0), climb(&trim, h1), climb(&dive, h2));
    println!("climb m/s: lift alone {c0:.4}, trimmed up {c1:.4}, trimmed down {c2:.4}");
    assert!(c1 > 5.0 * c0.max(0.001), "trimmed {c1} vs lift alone {c0}");
    assert!(c2 < -0.5 * c1, "the dive mirrors the climb: {c2} vs {c1}");
    assert!(
        lift.forward().z.abs() < 0.1,
        "lift alone pitched: {}",
        lift.forward()
    );
    let pitch = fmath::asin(trim.forward().z);
    assert!((0.15..=0.45).contains(&pitch), "pitch {pitch} rad");
    // Still upright: the trim tilts the back only in the plane of the heading.
    assert!(trim.up().z > 0.85, "rolled: {}", trim.up());
    // A zero gain restores the level body.
    let level = FishBody::with_params(
        LENGTH_M,
        Vec3::ZERO,
        Vec3::X,
        BodyParams {
            fin_trim_gain: 0.0,
            ..Default::default()
        },
    );
    let (level, _) = swim_from(level, SwimParams::MAX, PectoralFins::climb(0.3), secs);
    assert!(
        level.forward().z.abs() < 0.1,
        "gain 0 pitched: {}",
        level.forward()
    );
}

#[test]
fn braking_fins_reduce_speed() {
    let mut free = FishBody::new(LENGTH_M, Vec3::ZERO, Vec3::X);
    let mut braked = free.clone();
    for fish in [&mut free, &mut braked] {
        fish.set_uniform_velocity_m_per_s(Vec3::X * 0.2 * LENGTH_M);
    }
    let brake = BodyCommand {
        fins: PectoralFins::BRAKE,
        ..Default::default()
    };
    for _ in 0..40 {
        free.step(&BodyCommand::default(), Vec3::ZERO);
        braked.step(&brake, Vec3::ZERO);
    }
    let (v_free, v_braked) = (free.velocity_m_per_s().x, braked.velocity_m_per_s().x);
    assert!(v_braked < 0.8 * v_free, "braked {v_braked} free {v_free}");
}

/// Top speed (the swim-MC's maximal parameters, body lengths/s) and the heading
/// change of the four key turns of `SteeringMap::DEFAULT` (30/45/60/90°, left,
/// degrees) on a body with `body` parameters, the controllers sampled as
/// `sampling` says.
fn resolution_row(body: BodyParams, sampling: ControlSampling) -> (f32, [f32; 4]) {
    use crate::sim::body::turn_mc::{SteeringMap, TurnDirection, measure_turn_deg_with};
    let top = speed_with(SwimParams::MAX, body, sampling);
    let turns = SteeringMap::DEFAULT
        .keys
        .map(|(_, p)| measure_turn_deg_with(p, TurnDirection::Left, body, sampling));
    (top, turns)
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

/// The convergence table of `docs/fish-body.md`: top speed (3 Hz) and the key
/// turns against integrator, control sampling and substeps, plus the speed at
/// other frequencies.
/// `cargo test --release --lib convergence_table -- --ignored --nocapture`.
#[test]
#[ignore]
fn convergence_table() {
    let rows: [(Integrator, ControlSampling, u32, u32); 17] = [
        (Integrator::BackwardEuler, ControlSampling::PerStep, 8, 1),
        (Integrator::BackwardEuler, ControlSampling::PerStep, 16, 1),
        (Integrator::BackwardEuler, ControlSampling::PerStep, 32, 1),
        (Integrator::BackwardEuler, ControlSampling::PerSubstep, 8, 1),
        (
            Integrator::BackwardEuler,
            ControlSampling::PerSubstep,
            16,
            1,
        ),
        (
            Integrator::BackwardEuler,
            ControlSampling::PerSubstep,
            32,
            1,
        ),
        (
            Integrator::BackwardEuler,
            ControlSampling::PerSubstep,
            64,
            1,
        ),
        (Integrator::Bdf2, ControlSampling::PerSubstep, 8, 1),
        (Integrator::Bdf2, ControlSampling::PerSubstep, 12, 1),
        (Integrator::Bdf2, ControlSampling::PerSubstep, 12, 2),
        (Integrator::Bdf2, ControlSampling::PerSubstep, 12, 3),
        (Integrator::Bdf2, ControlSampling::PerSubstep, 16, 1),
        (Integrator::Bdf2, ControlSampling::PerSubstep, 16, 2),
        (Integrator::Bdf2, ControlSampling::PerSubstep, 16, 4),
        (Integrator::Bdf2, ControlSampling::PerSubstep, 24, 4),
        (Integrator::Bdf2, ControlSampling::PerSubstep, 32, 4),
        (Integrator::Bdf2, ControlSampling::PerSubstep, 64, 8),
    ];
    println!(
        "| integrator | controllers sampled | substeps | matrix every | 1 Hz | 2 Hz | top | 3 Hz | 4 Hz | 5 Hz | 30° key | 45° key | 60° key | 90° key |"
    );
    for (integrator, sampling, substeps, interval) in rows {
        let body = BodyParams {
            integrator,
            substeps,
            jacobian_interval: interval,
            ..Default::default()
        };
        let (top, turns) = resolution_row(body, sampling);
        let speed = |f: f32| speed_with(with(1.0, f), body, sampling);
        println!(
            "| {integrator:?} | {sampling:?} | {substeps} | {interval} | {:.3} | {:.3} | {top:.3} | {:.3} | {:.3} | {:.3} | {:.1}° | {:.1}° | {:.1}° | {:.1}° |",
            speed(1.0),
            speed(2.0),
            speed(3.0),
            speed(4.0),
            speed(5.0),
            turns[0],
            turns[1],
            turns[2],
            turns[3]
        );
    }
}

/// Behind the lag and frequency paragraphs of `docs/fish-body.md` and
/// `motor_controller.rs`: speed at 3 Hz against the posterior lag, and, against
/// the tail-beat frequency, the speed, the lateral amplitude of the last ring and
/// of the tail-fin tips, and how far the tail fin's sideways motion lags the last
/// ring's (degrees of the beat; a wave travels tailwards when the lag is
/// positive). `cargo test --release --lib wave_table -- --ignored --nocapture`.
#[test]
#[ignore]
fn wave_table() {
    use crate::sim::body::body_layout::{RING_COUNT, TAIL_FIN_NODES, ring_nodes};
    for lag_deg in [0.0f32, 30.0, 90.0, 180.0] {
        let mut fish = FishBody::new(LENGTH_M, Vec3::ZERO, Vec3::X);
        let mut mc = SwimMc::default();
        mc.posterior_lag_rad = lag_deg.to_radians();
        let dt = fish.dt_secs();
        let steps = (60.0 / dt) as usize;
        let mut half = Vec3::ZERO;
        for k in 0..steps {
            fish.step_with(&PectoralFins::NEUTRAL, Vec3::ZERO, |t| {
                mc.muscles_at(&SwimParams::MAX, t)
            });
            mc.advance(&SwimParams::MAX, dt);
            if k + 1 == steps / 2 {
                half = fish.centre_of_mass_m();
            }
        }
        let v = (fish.centre_of_mass_m() - half).x / 30.0 / LENGTH_M;
        println!(
            "lag {lag_deg}°: {v:.3} BL/s at {} Hz",
            SwimParams::MAX.anterior_frequency_hz
        );
    }
    println!(
        "| beat (Hz) | speed (BL/s) | last ring amplitude (BL) | tail-fin amplitude (BL) | tail-fin lag behind last ring (°) |"
    );
    for f in [1.0f32, 2.0, 3.0, 4.0, 4.25, 4.5, 5.0] {
        let mut fish = FishBody::new(LENGTH_M, Vec3::ZERO, Vec3::X);
        let mut mc = SwimMc::default();
        let params = with(1.0, f);
        let dt = fish.dt_secs();
        let steps = (40.0 / dt) as usize;
        let mut half = Vec3::ZERO;
        // Fourier projections of the sideways positions at the beat frequency.
        let (mut ring, mut tail) = ((0.0f32, 0.0f32), (0.0f32, 0.0f32));
        let mut samples = 0;
        for k in 0..steps {
            fish.step_with(&PectoralFins::NEUTRAL, Vec3::ZERO, |t| {
                mc.muscles_at(&params, t)
            });
            mc.advance(&params, dt);
            if k + 1 == steps / 2 {
                half = fish.centre_of_mass_m();
            }
            if k >= steps / 2 {
                let p = fish.positions_m();
                let centre = fish.centre_of_mass_m().y;
                let last = ring_nodes(RING_COUNT - 1)
                    .iter()
                    .map(|&i| p[i].y)
                    .sum::<f32>()
                    / 4.0
                    - centre;
                let fin = (p[TAIL_FIN_NODES[0]].y + p[TAIL_FIN_NODES[1]].y) / 2.0 - centre;
                let phase = std::f32::consts::TAU * f * (k + 1) as f32 * dt;
                ring.0 += last * fmath::cos(phase);
                ring.1 += last * fmath::sin(phase);
                tail.0 += fin * fmath::cos(phase);
                tail.1 += fin * fmath::sin(phase);
                samples += 1;
            }
        }
        let n = samples as f32 / 2.0;
        let amplitude = |c: (f32, f32)| (c.0 * c.0 + c.1 * c.1).sqrt() / n / LENGTH_M;
        let angle = |c: (f32, f32)| fmath::atan2(c.1, c.0);
        let lag = (angle(tail) - angle(ring)).to_degrees();
        let lag = (lag + 540.0).rem_euclid(360.0) - 180.0;
        let v = (fish.centre_of_mass_m() - half).x / 20.0 / LENGTH_M;
        println!(
            "| {f} | {v:.3} | {:.3} | {:.3} | {lag:.0} |",
            amplitude(ring),
            amplitude(tail)
        );
    }
}

/// Tuning routine behind the table in `motor_controller.rs`:
/// `cargo test --release speed_table -- --ignored --nocapture`.
#[test]
#[ignore]
fn speed_table() {
    let top = SwimParams::MAX.anterior_frequency_hz;
    for (r, f) in [
        (1.0, 0.5),
        (1.0, 1.0),
        (1.0, 1.5),
        (1.0, 2.0),
        (1.0, top),
        (1.0, 2.5),
        (1.0, 3.0),
        (1.0, 4.0),
        (1.0, 5.0),
        (0.75, top),
        (0.5, top),
        (0.25, top),
    ] {
        println!("| {r:.1} | {f:.2} | {:.3} |", speed_bl_per_s(with(r, f)));
    }
    let mut fish = FishBody::new(LENGTH_M, Vec3::ZERO, Vec3::X);
    let mut mc = SwimMc::default();
    let n = 20_000;
    let t0 = std::time::Instant::now();
    for _ in 0..n {
        let u = mc.step(&SwimParams::MAX, fish.dt_secs());
        fish.step(
            &BodyCommand {
                muscle_contractions: u,
                ..Default::default()
            },
            Vec3::ZERO,
        );
    }
    println!(
        "cost per step: {:.1} µs",
        t0.elapsed().as_secs_f64() * 1e6 / n as f64
    );
}

/// Timing of [`FishBody::step`] behind the figures in the `fish_body.rs` module doc:
/// `cargo test --release --lib step_cost -- --ignored --nocapture`. A fish swimming
/// at top speed (tail beating, water faces switching), after a 10 s warm-up; seven
/// batches of 2000 steps, min and median reported (the machine may be shared). Once
/// with the default exact Jacobian, then with `jacobian_interval` 2 and 4.
#[test]
#[ignore]
fn step_cost() {
    // Configurations: (integrator, substeps, jacobian interval); `STEP_COST` =
    // "bdf2:24:4,euler:8:1" overrides the list.
    let configs: Vec<(Integrator, u32, u32)> = std::env::var("STEP_COST")
        .ok()
        .map(|s| {
            s.split(',')
                .filter_map(|c| {
                    let mut parts = c.split(':');
                    let integrator = match parts.next()? {
                        "euler" => Integrator::BackwardEuler,
                        _ => Integrator::Bdf2,
                    };
                    Some((
                        integrator,
                        parts.next()?.parse().ok()?,
                        parts.next()?.parse().ok()?,
                    ))
                })
                .collect()
        })
        .unwrap_or_else(|| {
            let d = BodyParams::default();
            vec![(d.integrator, d.substeps, d.jacobian_interval)]
        });
    for (integrator, substeps, interval) in configs {
        let params = BodyParams {
            integrator,
            substeps,
            jacobian_interval: interval,
            ..Default::default()
        };
        let mut fish = FishBody::with_params(LENGTH_M, Vec3::ZERO, Vec3::X, params);
        let mut mc = SwimMc::default();
        let mut step = |fish: &mut FishBody| {
            let dt = fish.dt_secs();
            fish.step_with(&PectoralFins::NEUTRAL, Vec3::ZERO, |t| {
                mc.muscles_at(&SwimParams::MAX, t)
            });
            mc.advance(&SwimParams::MAX, dt);
        };
        for _ in 0..(10.0 / fish.dt_secs()) as usize {
            step(&mut fish);
        }
        let batch = 2000;
        let mut micros: Vec<f64> = (0..7)
            .map(|_| {
                let t0 = std::time::Instant::now();
                for _ in 0..batch {
                    step(&mut fish);
                }
                t0.elapsed().as_secs_f64() * 1e6 / batch as f64
            })
            .collect();
        micros.sort_by(f64::total_cmp);
        let n = f64::from(substeps);
        println!(
            "{integrator:?}, {substeps} substeps, jacobian_interval {interval}: step cost min \
             {:.1} µs, median {:.1} µs per step; {:.2} / {:.2} µs per substep",
            micros[0],
            micros[3],
            micros[0] / n,
            micros[3] / n
        );
        assert!(fish.positions_m().iter().all(|p| p.is_finite()));
    }
}

/// Search routine behind `SteeringMap::DEFAULT` and the turn table in `turn_mc.rs`:
/// `cargo test --release turn_table -- --ignored --nocapture`.
#[test]
#[ignore]
fn turn_table() {
    use crate::sim::body::turn_mc::{
        TurnDirection, TurnMc, find_steering_map, measure_heading_change_deg, measure_turn_deg,
    };
    let (map, measured) = find_steering_map();
    for ((deg, p), m) in map.keys.iter().zip(measured) {
        println!(
            "| {deg:.0} | {:.4} | {:.1} | {:.4} | {:.1} | {m:.1} | right {:.1} |",
            p.anterior_amplitude,
            p.anterior_rate_per_sec,
            p.posterior_amplitude,
            p.posterior_rate_per_sec,
            measure_turn_deg(*p, TurnDirection::Right)
        );
    }
    let mc = TurnMc::default();
    for deg in [10.0, 20.0, 35.0, 50.0, 75.0] {
        let p = mc.map.params_for_angle(deg);
        let l = measure_turn_deg(p, TurnDirection::Left);
        let r = measure_turn_deg(p, TurnDirection::Right);
        let secs = p.duration_secs(mc.restore_rate_ratio);
        println!("{deg}° → {l:.1}° / {r:.1}° in {secs:.1} s");
    }
    for deg in [135.0, 180.0] {
        let mut seq = TurnMc::default();
        seq.start_turn(deg);
        println!(
            "sequence {deg}° → {:.1}°",
            measure_heading_change_deg(&mut seq, false)
        );
    }
}

mod turning {
    use crate::sim::body::turn_mc::{
        SteeringMap, TurnDirection, TurnMc, measure_heading_change_deg, measure_turn_deg,
        mirror_muscles,
    };

    #[test]
    fn each_key_turn_lands_within_10_degrees_of_its_target() {
        for (target, params) in SteeringMap::DEFAULT.keys {
            let left = measure_turn_deg(params, TurnDirection::Left);
            let right = measure_turn_deg(params, TurnDirection::Right);
            assert!((left - target).abs() <= 10.0, "left {target}°: {left}°");
            assert!((right + target).abs() <= 10.0, "right {target}°: {right}°");
        }
    }

    #[test]
    fn left_and_right_turns_are_mirror_images() {
        // The controller: a right turn contracts exactly the mirror muscles.
        let (mut left, mut right) = (TurnMc::default(), TurnMc::default());
        left.start_turn(50.0);
        right.start_turn(-50.0);
        let mut steps = 0;
        while left.is_turning() || right.is_turning() {
            let (l, r) = (left.step(0.055), right.step(0.055));
            assert_eq!(mirror_muscles(&l), r);
            steps += 1;
            assert!(steps < 10_000);
        }
        assert!(steps > 10);
        // The body: mirror-image turns, up to rounding.
        let params = SteeringMap::DEFAULT.params_for_angle(50.0);
        let l = measure_turn_deg(params, TurnDirection::Left);
        let r = measure_turn_deg(params, TurnDirection::Right);
        assert!(l > 0.0 && (l + r).abs() < 0.5, "left {l}° right {r}°");
    }

    #[test]
    fn steering_map_is_monotonic_in_angle() {
        let map = SteeringMap::DEFAULT;
        let mut previous = map.params_for_angle(0.0);
        assert_eq!(previous.anterior_amplitude, 0.0);
        for deg in 1..=90 {
            let p = map.params_for_angle(deg as f32);
            assert!(p.anterior_amplitude > previous.anterior_amplitude, "{deg}°");
            assert!(
                p.posterior_amplitude > previous.posterior_amplitude,
                "{deg}°"
            );
            previous = p;
        }
        // Beyond 90° a single turn saturates; the sign only picks the side.
        assert_eq!(map.params_for_angle(120.0), map.params_for_angle(90.0));
        assert_eq!(map.params_for_angle(-40.0), map.params_for_angle(40.0));
        // The measured turn grows with the requested angle and follows it.
        let mut last = f32::NEG_INFINITY;
        for deg in [10.0, 20.0, 35.0, 50.0, 75.0, 90.0] {
            let got = measure_turn_deg(map.params_for_angle(deg), TurnDirection::Left);
            assert!(got > last, "{deg}°: {got}° after {last}°");
            assert!((got - deg).abs() <= 10.0, "{deg}° requested, {got}° turned");
            last = got;
        }
    }

    #[test]
    fn turns_beyond_90_degrees_are_sequences_of_smaller_turns() {
        let mut mc = TurnMc::default();
        mc.start_turn(180.0);
        // Two 90° turns back to back: the anterior muscle rises twice.
        let mut rises = 0;
        let mut previous = 0.0;
        let mut rising = false;
        while mc.is_turning() {
            let u = mc.step(0.055)[0];
            if u > previous && !rising {
                rises += 1;
            }
            rising = u > previous;
            previous = u;
        }
        assert_eq!(rises, 2);
        let mut mc = TurnMc::default();
        mc.start_turn(-180.0);
        let turned = measure_heading_change_deg(&mut mc, true);
        assert!((turned + 180.0).abs() <= 20.0, "turned {turned}°");
    }
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
