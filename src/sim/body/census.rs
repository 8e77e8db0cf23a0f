//! This folder's measurement scripts (see [`crate::census`]): the body's
//! convergence, swimming, turning and steering tables and the cost of a step,
//! quoted by `docs/fish-body.md`, `docs/benchmarks.md` and the module docs of
//! `fish_body.rs`, `motor_controller.rs`, `turn_mc.rs` and `banded_cholesky.rs`.
//! The runs they share with the tests are in `swim_trials.rs` and
//! `physical_fish/trials.rs`.

use glam::Vec3;
use std::f32::consts::PI;

use crate::census::Census;
use crate::sim::body::banded_cholesky::{SYSTEM_SIZE, fish_like};
use crate::sim::body::motor_bridge::{MotorParams, level_turn_deg};
use crate::sim::body::physical_fish::trials::{
    CRUISE, about_turn, closed_loop_turn, closed_loop_turn_with, cruising_fish, held_bend,
    open_loop_steer, straight_speed_at_amplitude, turn_at_speed_after_deg, turn_at_speed_deg,
    turn_with_map_deg,
};
use crate::sim::body::swim_trials::{LENGTH_M, resolution_row, speed_bl_per_s, speed_with, with};
use crate::sim::body::{
    BodyCommand, BodyParams, ControlSampling, FishBody, Integrator, PectoralFins, SwimMc,
    SwimParams,
};
use crate::sim::common::fmath;

/// The scripts, in the order `shoal-census` lists them.
pub const CENSUSES: &[Census] = &[
    Census {
        name: "convergence-table",
        about: "speed and key turns against integrator, sampling and substeps (docs/fish-body.md, Convergence)",
        run: convergence_table,
    },
    Census {
        name: "wave-table",
        about: "speed against posterior lag; tail wave against beat frequency (docs/fish-body.md, motor_controller.rs)",
        run: wave_table,
    },
    Census {
        name: "speed-table",
        about: "speed against amplitude and beat frequency, cost per step (docs/fish-body.md, Swimming)",
        run: speed_table,
    },
    Census {
        name: "step-cost",
        about: "time per body step and substep; STEP_COST=bdf2:24:4,... (fish_body.rs, docs/benchmarks.md)",
        run: step_cost,
    },
    Census {
        name: "factorize-and-solve-cost",
        about: "time of one banded factorisation and solve (banded_cholesky.rs)",
        run: factorize_and_solve_cost,
    },
    Census {
        name: "turn-table",
        about: "searches the steering map's four keys and measures its turns (turn_mc.rs, docs/fish-body.md)",
        run: turn_table,
    },
    Census {
        name: "amplitude-speed-curve",
        about: "straight speed against swim amplitude (motor_controller.rs SPEED_AT_AMPLITUDE)",
        run: amplitude_speed_curve,
    },
    Census {
        name: "keys-over-swim-speeds",
        about: "bisects each turn key over the swim speeds the minds ask for (SteeringMap::DEFAULT)",
        run: keys_over_swim_speeds,
    },
    Census {
        name: "key-turns-against-swim-speed",
        about: "each key turn at 0-1 of the top speed (docs/fish-body.md, docs/fish-mind.md)",
        run: key_turns_against_swim_speed,
    },
    Census {
        name: "key-turns-against-request-time",
        about: "key turns against speed and the beat step requested at (docs/fish-body.md, KEY_BEAT_PHASE_RAD)",
        run: key_turns_against_request_time,
    },
    Census {
        name: "steer-sweep",
        about: "open-loop heading rate and radius of a held bend for twelve sets of steering biases",
        run: steer_sweep,
    },
    Census {
        name: "closed-loop-turn-times",
        about: "seconds to 90 % of closed-loop turns, shortest spine; STEER_BIASES=... (docs/fish-body.md, fish_body.rs)",
        run: closed_loop_turn_times,
    },
    Census {
        name: "turn-agility",
        about: "time, peak rate and radius of closed-loop turns through the bridge (docs/fish-body.md, Agility)",
        run: turn_agility,
    },
    Census {
        name: "about-turns",
        about: "time and width of an about-turn with the full bend, from four lead-in speeds (docs/fish-body.md)",
        run: about_turns,
    },
    Census {
        name: "climb-angle",
        about: "climb angle, rise and level turn rate with climbing fins and trim limits (docs/fish-body.md, docs/departures.md)",
        run: climb_angle,
    },
    Census {
        name: "held-bend-radius",
        about: "speed, turn rate and radius of a held full bend against swim setting and fins (docs/fish-body.md)",
        run: held_bend_radius,
    },
];

/// The convergence table of `docs/fish-body.md`: top speed (3 Hz) and the key
/// turns against integrator, control sampling and substeps, plus the speed at
/// other frequencies.
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
/// positive).
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

/// Tuning routine behind the speed table in `motor_controller.rs` and
/// `docs/fish-body.md` ("Swimming"): speed at full amplitude against the
/// tail-beat frequency and at the top frequency against the amplitude (60 s
/// runs, speed over the last 30 s, body lengths/s), then the cost of a step.
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

/// Timing of [`FishBody::step`] behind the figures in the `fish_body.rs` module
/// doc, `docs/fish-body.md` and `docs/benchmarks.md`. A fish swimming at top speed (tail beating, water faces switching), after a 10 s warm-up; seven
/// batches of 2000 steps, min and median reported (the machine may be shared). Once
/// with the default exact Jacobian, then with `jacobian_interval` 2 and 4.
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

/// Search routine behind `SteeringMap::DEFAULT` and the turn table in
/// `turn_mc.rs` and `docs/fish-body.md`: the four keys found and measured to
/// either side, the turns between keys, and turns beyond 90° as sequences.
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

/// Behind `body::motor_controller::SPEED_AT_AMPLITUDE`: a 0.5 m fish's straight
/// speed at amplitude 0, 0.05, …, 1 (m/s and as a share of full amplitude).
fn amplitude_speed_curve() {
    let full = straight_speed_at_amplitude(1.0);
    for i in 0..=20 {
        let a = i as f32 / 20.0;
        let v = straight_speed_at_amplitude(a);
        println!("| {a:.2} | {v:.4} m/s | {:.3} |", v / full);
    }
}

/// Behind `SteeringMap::DEFAULT`: each key's r bisected so that its turn,
/// averaged over the swim speeds the minds ask for (0.3, 0.6 and 1.0 of the
/// top speed), is the key's angle; prints r and the turn from 0, 0.3, 0.6 and
/// 1.0 of the top speed.
fn keys_over_swim_speeds() {
    use crate::sim::body::turn_mc::{SteeringMap, key};
    let mut map = SteeringMap::DEFAULT;
    for k in 0..4 {
        let target = map.keys[k].0;
        let mean = |map: SteeringMap| {
            [0.3, 0.6, 1.0]
                .iter()
                .map(|&s| turn_with_map_deg(map, target, s, 0))
                .sum::<f32>()
                / 3.0
        };
        let (mut lo, mut hi) = (0.0f32, 1.0f32);
        for _ in 0..14 {
            let mid = 0.5 * (lo + hi);
            map.keys[k].1 = key(mid);
            if mean(map) < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let r = 0.5 * (lo + hi);
        map.keys[k].1 = key(r);
        let row: Vec<String> = [0.0, 0.3, 0.6, 1.0]
            .iter()
            .map(|&s| format!("{:.1}", turn_with_map_deg(map, target, s, 0)))
            .collect();
        println!("| {target}° | {r:.4} | {} |", row.join(" | "));
    }
}

/// Behind the key-turn table of `docs/fish-mind.md`: the turn of each key
/// (30/45/60/90°) asked of a physical fish swimming at 0, 0.3, 0.6 and 1.0 of
/// its top speed, degrees.
fn key_turns_against_swim_speed() {
    for key in [30.0, 45.0, 60.0, 90.0] {
        let row: Vec<String> = [0.0, 0.3, 0.6, 1.0]
            .iter()
            .map(|&s| format!("{:6.1}", turn_at_speed_deg(key, s)))
            .collect();
        println!("| {key}° | {} |", row.join(" | "));
    }
}

/// Behind `body::turn_mc::KEY_BEAT_PHASE_RAD`: the key turns against the swim
/// speed and the step at which they are requested (0–7 steps later: one tail
/// beat), degrees.
fn key_turns_against_request_time() {
    for key in [30.0, -30.0, 60.0, -60.0, 90.0, -90.0] {
        for speed in [0.3, 0.6, 1.0] {
            let row: Vec<String> = (0..8)
                .map(|k| format!("{:.1}", turn_at_speed_after_deg(key, speed, k)))
                .collect();
            println!("| {key}° | {speed} | {} |", row.join(" | "));
        }
    }
}

/// Behind the choice of the steering biases: the open-loop heading rate of a
/// held bend (full left, full right, half left; °/s) and the path's radius
/// (body lengths) at full and half speed, for twelve sets of segment biases.
fn steer_sweep() {
    for biases in [
        [1.0, 1.0, 0.5],
        [1.0, 1.0, 0.0],
        [1.0, 0.5, 0.0],
        [1.0, 0.0, 0.0],
        [0.5, 0.5, 0.0],
        [0.5, 0.0, 0.0],
        [0.5, 0.5, 0.5],
        [0.3, 0.3, 0.3],
        [0.3, 0.3, 0.0],
        [0.3, 0.0, 0.0],
        [0.2, 0.2, 0.2],
        [0.0, 0.0, 0.3],
    ] {
        for speed in [1.0, 0.5] {
            let (l, r) = open_loop_steer(speed, 1.0, biases);
            let (rr, _) = open_loop_steer(speed, -1.0, biases);
            let (half, _) = open_loop_steer(speed, 0.5, biases);
            println!(
                "biases {biases:?} speed {speed}: left {l:5.1}°/s right {rr:5.1}°/s half {half:5.1}°/s radius {r:4.2} BL"
            );
        }
    }
}

/// Behind the steering biases of `MotorParams` (`steer_anterior_bias`, …):
/// closed-loop turns of ±90° and ±30° from 1.0, 0.7, 0.4 and 0.2 of the top
/// speed, each started at three tail-beat phases (3.0, 3.2, 3.4 s of lead-in);
/// prints the seconds to 90 % of each turn ("never" = not within 15 s), the
/// worst and the shortest spine. `STEER_BIASES="0.5,0.5,0.25;1,1,0.5"`
/// measures other biases. Quoted in `fish_body.rs` and `docs/fish-body.md`.
fn closed_loop_turn_times() {
    let list: Vec<[f32; 3]> = std::env::var("STEER_BIASES")
        .ok()
        .map(|v| {
            v.split(';')
                .filter_map(|b| {
                    let x: Vec<f32> = b.split(',').filter_map(|y| y.parse().ok()).collect();
                    (x.len() == 3).then(|| [x[0], x[1], x[2]])
                })
                .collect()
        })
        .unwrap_or_else(|| vec![MotorParams::default().steer_biases()]);
    for biases in list {
        println!("biases {biases:?}");
        let (mut worst, mut shortest, mut never) = (0.0f32, 1.0f32, 0);
        for speed in [1.0, 0.7, 0.4, 0.2] {
            let mut row = format!("  from {speed} of top speed:");
            for angle in [90.0, -90.0, 30.0, -30.0] {
                for lead in [3.0, 3.2, 3.4] {
                    let (secs, spine) = closed_loop_turn_with(angle, speed, lead, biases);
                    shortest = shortest.min(spine);
                    match secs {
                        Some(s) => {
                            worst = worst.max(s);
                            row += &format!(" {s:.1}");
                        }
                        None => {
                            never += 1;
                            row += " never";
                        }
                    }
                }
            }
            println!("{row}");
        }
        println!("  worst {worst:.1} s, {never} never, shortest spine {shortest:.2} of the length");
    }
}

/// Turn measurements of the physical fish driven through the bridge, for
/// `docs/fish-body.md` ("Agility"): closed-loop turns of 30, 90, 179 and −90°
/// from 1.0, 0.7 and 0.4 of the top speed; time to 90 % of the turn, peak
/// heading rate and turning radius.
fn turn_agility() {
    for speed in [1.0, 0.7, 0.4] {
        for angle in [30.0, 90.0, 179.0, -90.0] {
            let (secs, peak, radius) = closed_loop_turn(angle, speed);
            println!(
                "speed {speed:.1} angle {angle:6.1}°: 90 % in {secs:5.2} s, peak {peak:5.1}°/s, radius {radius:4.2} BL"
            );
        }
    }
}

/// Behind `docs/fish-body.md` ("Foraging agility"): how fast and how wide a
/// fish turns about with the full bend, from lead-ins at 0.7, 0.4, 0.2 and 0 of
/// its top speed, swimming at 1.0, 0.7 and 0.4, fins neutral or the inner one
/// braking: seconds to 90° and 180°, and the loop's width in body lengths.
fn about_turns() {
    let inner_brake = PectoralFins {
        left_angle_rad: PI,
        ..PectoralFins::NEUTRAL
    };
    for (name, fins) in [
        ("neutral", PectoralFins::NEUTRAL),
        ("inner brake", inner_brake),
    ] {
        for lead in [0.7, 0.4, 0.2, 0.0] {
            for speed in [1.0, 0.7, 0.4] {
                let (t90, t180, width) = about_turn(lead, speed, fins);
                println!(
                    "{name:12} from {lead:3.1}, swim {speed:3.1}: 90° in {t90:4.1} s, 180° in {t180:4.1} s, loop {width:4.2} BL"
                );
            }
        }
    }
}

/// Climb angle and speed of a fish at 0.7 of the top speed with the fins
/// climbing at `pitch` and the trim limited to `max_trim`, and its level
/// turn rate with the full bend meanwhile; quoted by `docs/fish-body.md` and
/// `docs/departures.md` (fin trim).
fn climb_angle() {
    for (pitch, max_trim) in [
        (0.5, 0.5),
        (0.7, 0.7),
        (0.8, 0.8),
        (1.0, 1.0),
        (1.2, 1.2),
        (1.0, 0.5),
    ] {
        for steer in [0.0, 1.0] {
            let mut fish = cruising_fish(|f| f.body_mut().params_mut().max_trim_rad = max_trim);
            let dt = fish.body().dt_secs();
            let mut intent = CRUISE;
            intent.fins = PectoralFins::climb(pitch);
            intent.steer = steer;
            intent.speed_fraction = 0.7f32.max(steer);
            for _ in 0..(4.0 / dt) as usize {
                fish.step(&intent, Vec3::ZERO);
            }
            let (from, h0) = (fish.point.position_m, fish.heading());
            let (mut turned, mut prev) = (0.0f32, h0);
            let steps = (4.0 / dt) as usize;
            for _ in 0..steps {
                fish.step(&intent, Vec3::ZERO);
                turned += level_turn_deg(prev, fish.heading());
                prev = fish.heading();
            }
            let d = fish.point.position_m - from;
            let secs = steps as f32 * dt;
            let level = Vec3::new(d.x, 0.0, d.z).length();
            println!(
                "fins {pitch:.1} trim<= {max_trim:.1} steer {steer}: climb {:5.1}°, rise {:5.3} m/s, level turn {:5.1}°/s, spine {:.2}",
                crate::sim::common::fmath::atan2(d.y, level).to_degrees(),
                d.y / secs,
                turned / secs,
                fish.body().spine_length_m() / 0.5
            );
        }
    }
}

/// How the held bend's turning circle depends on the tail beat and the fins,
/// for issue 13 (can a fish that slows down or brakes turn tighter?) and
/// `docs/fish-body.md`: a 0.5 m fish swims straight at 0.7 of its top speed for
/// 4 s, then holds the full bend (steer 1) with a swim-MC setting and fins for
/// 8 s. Prints its speed, heading rate and path radius over the last 6 s.
fn held_bend_radius() {
    let inner_brake = PectoralFins {
        left_angle_rad: PI,
        ..PectoralFins::NEUTRAL
    };
    let outer_brake = PectoralFins {
        right_angle_rad: PI,
        ..PectoralFins::NEUTRAL
    };
    for (name, fins) in [
        ("neutral", PectoralFins::NEUTRAL),
        ("both brake", PectoralFins::BRAKE),
        ("inner brake", inner_brake),
        ("outer brake", outer_brake),
    ] {
        for speed in [1.0, 0.7, 0.5, 0.3, 0.15, 0.0] {
            let (v, rate, radius) = held_bend(speed, fins);
            println!(
                "{name:12} swim {speed:4.2}: speed {v:5.3} m/s, {rate:6.1}°/s, radius {radius:5.2} BL"
            );
        }
    }
}

/// The cost of the banded solver behind the `banded_cholesky.rs` module doc: a
/// copy and factorisation of a fish-like matrix, and a solve, µs each (mean of
/// 200 000).
fn factorize_and_solve_cost() {
    let m = fish_like(11);
    let n = 200_000;
    let mut f = m.clone();
    let t0 = std::time::Instant::now();
    for _ in 0..n {
        f.clone_from(std::hint::black_box(&m));
        f.factorize();
    }
    let factor_us = t0.elapsed().as_secs_f64() * 1e6 / n as f64;
    let mut rhs = [1.0; SYSTEM_SIZE];
    let t0 = std::time::Instant::now();
    for _ in 0..n {
        f.solve(std::hint::black_box(&mut rhs));
    }
    let solve_us = t0.elapsed().as_secs_f64() * 1e6 / n as f64;
    println!("copy + factorize {factor_us:.2} µs, solve {solve_us:.2} µs");
    assert!(rhs.iter().all(|x| x.is_finite()));
}
