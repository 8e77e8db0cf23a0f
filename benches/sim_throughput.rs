//! Native benchmark: simulation throughput and the CPU side of a frame.
//!
//! Run with `./dev bench` (or `cargo bench --bench sim_throughput`; add
//! `-- 20000` to time only the boid layer with that many fish, e.g. under
//! `perf`). Prints figures; asserts nothing. The in-browser counterpart is the `?bench` page mode.
//!
//! `cargo test --all-targets` runs it too, without `--bench`: then each case runs
//! once, smallest fish count only, as a check that the benchmark still works (its
//! full run takes two minutes in a debug build and its figures would mean nothing).

use std::sync::OnceLock;
use std::time::{Duration, Instant};

use shoal::lab::Lab;
use shoal::render::{FrameBuilder, OrbitCamera};
use shoal::settings::{Scene, Settings};
use shoal::sim::boids::world::SPATIAL_METRICS_EVERY_STEPS;
use shoal::sim::common::school_metrics::{SchoolMeter, order_parameters};
use shoal::sim::learning::Trainer;
use shoal::sim::reef::world::ReefBodyKind;
use shoal::sim::{BoidParams, World, WorldConfig};

/// Whether this is a check run (`cargo test`) and not a benchmark (`cargo bench`,
/// which passes `--bench`).
fn check_run() -> bool {
    static CHECK: OnceLock<bool> = OnceLock::new();
    *CHECK.get_or_init(|| !std::env::args().any(|a| a == "--bench"))
}

/// The fish counts to time: all of them, or in a check run the first.
fn cases<T: Copy>(all: &[T]) -> Vec<T> {
    if check_run() {
        all[..1].to_vec()
    } else {
        all.to_vec()
    }
}

/// Steps to settle a scene before timing it (one in a check run).
fn warm_up(steps: usize) -> usize {
    if check_run() { 1 } else { steps }
}

/// Runs `f` repeatedly for about `budget` (once in a check run), returning calls
/// per second.
fn rate(budget: Duration, mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    let mut calls = 0u64;
    while calls == 0 || (start.elapsed() < budget && !check_run()) {
        f();
        calls += 1;
    }
    calls as f64 / start.elapsed().as_secs_f64()
}

fn world(fish_count: usize) -> World {
    World::new(WorldConfig {
        seed: 1,
        fish_count,
        ..WorldConfig::default()
    })
}

fn main() {
    println!("Shoal native benchmark (one thread)");
    if check_run() {
        println!(
            "A check run (no --bench): each case once, figures meaningless; `cargo bench` times them."
        );
    }
    println!();
    println!("Boid layer, group preset (7 nearest seen neighbours, 5 m vision), metrics included:");
    println!(
        "(metrics: polarization, milling and speed every step; NND and groups every {} steps)",
        SPATIAL_METRICS_EVERY_STEPS
    );
    println!(
        "{:>7} | {:>10} | {:>14} | {:>15} | {:>16} | {:>16}",
        "fish", "steps/s", "boid-steps/s", "full metrics ms", "every-step ms", "metrics ms/step"
    );
    let only: Option<usize> = std::env::args().skip(1).find_map(|a| a.parse().ok());
    for fish_count in cases(&[500, 5_000, 20_000, 50_000]) {
        if only.is_some_and(|n| n != fish_count) {
            continue;
        }
        let mut w = world(fish_count);
        w.set_boids(Some(BoidParams::group()));
        // Let the school form first: a dense school is the hard case.
        for _ in 0..warm_up(if fish_count > 5_000 { 300 } else { 600 }) {
            w.step();
        }
        let steps_per_sec = rate(Duration::from_secs(3), || w.step());
        let mut meter = SchoolMeter::default();
        let (lo, hi) = (w.tank().min_m, w.tank().max_m);
        let full_per_sec = rate(Duration::from_secs(1), || {
            std::hint::black_box(meter.measure(w.fish(), lo, hi));
        });
        let order_per_sec = rate(Duration::from_secs(1), || {
            std::hint::black_box(order_parameters(w.fish()));
        });
        let (full_ms, order_ms) = (1000.0 / full_per_sec, 1000.0 / order_per_sec);
        let every = SPATIAL_METRICS_EVERY_STEPS as f64;
        println!(
            "{fish_count:>7} | {steps_per_sec:>10.1} | {:>14.0} | {full_ms:>15.3} | {order_ms:>16.3} | {:>16.3}",
            steps_per_sec * fish_count as f64,
            (full_ms + (every - 1.0) * order_ms) / every
        );
    }
    println!();
    println!("Wandering fish (no boid layer) and the frame build:");
    println!(
        "{:>7} | {:>12} | {:>16} | {:>17}",
        "fish", "steps/s", "fish-steps/s", "frame build (ms)"
    );
    for fish_count in cases(&[200, 2_000, 5_000, 20_000]) {
        if only.is_some() {
            break;
        }
        let mut world = world(fish_count);
        for _ in 0..warm_up(60) {
            world.step();
        }
        let steps_per_sec = rate(Duration::from_secs(2), || world.step());

        let mut settings = Settings::default();
        settings.left.fish_count = fish_count as u32;
        let lab = Lab::new(settings);
        let tank = lab.scene().tank();
        let camera = OrbitCamera::framing(tank.min_m, tank.max_m, 16.0 / 9.0);
        let mut builder = FrameBuilder::default();
        let frames_per_sec = rate(Duration::from_secs(1), || {
            std::hint::black_box(builder.build(&lab.runs()[0], 1.0, &camera, [1920, 1080], 0.0, 0));
        });
        println!(
            "{fish_count:>7} | {steps_per_sec:>12.0} | {:>16.0} | {:>17.3}",
            steps_per_sec * fish_count as f64,
            1000.0 / frames_per_sec
        );
    }

    println!();
    let body = shoal::sim::body::BodyParams::default();
    println!(
        "Muscle-driven fish (Tu & Terzopoulos body, schooling, Δt = 0.055 s, {:?}, {} substeps, matrix every {}):",
        body.integrator, body.substeps, body.jacobian_interval
    );
    println!(
        "{:>7} | {:>10} | {:>14} | {:>19} | {:>17}",
        "fish", "steps/s", "fish-steps/s", "× real time (1/Δt)", "frame build (ms)"
    );
    for fish_count in cases(&[10u32, 50, 200]) {
        if only.is_some() {
            break;
        }
        let mut settings = Settings {
            scene: Scene::Physics,
            ..Settings::default()
        };
        settings.physics.fish_count = fish_count;
        settings.physics.sharks = 0;
        let mut lab = Lab::new(settings);
        lab.step(warm_up(40) as u32);
        let steps_per_sec = rate(Duration::from_secs(3), || lab.step(1));
        let tank = lab.scene().tank();
        let camera = OrbitCamera::framing(tank.min_m, tank.max_m, 16.0 / 9.0);
        let mut builder = FrameBuilder::default();
        let frames_per_sec = rate(Duration::from_secs(1), || {
            std::hint::black_box(builder.build(&lab.runs()[0], 0.5, &camera, [1920, 1080], 0.0, 0));
        });
        println!(
            "{fish_count:>7} | {steps_per_sec:>10.1} | {:>14.0} | {:>19.2} | {:>17.3}",
            steps_per_sec * f64::from(fish_count),
            steps_per_sec * lab.step_secs(),
            1000.0 / frames_per_sec
        );
    }

    println!();
    println!("Learning centre (Tu & Terzopoulos §4): simulated annealing, one forward simulation");
    println!("per evaluation (0.5 m fish, 2.5 s interval = 45 body steps, default body):");
    if only.is_none() {
        let mut trainer = Trainer::benchmark();
        trainer.run_evaluations(warm_up(20));
        let evaluations_per_sec = rate(Duration::from_secs(3), || {
            trainer.run_evaluations(1);
        });
        let steps = trainer.setup().steps() as f64;
        println!(
            "{:>22} | {:>16}\n{evaluations_per_sec:>22.1} | {:>16.0}",
            "evaluations/s",
            "body steps/s",
            evaluations_per_sec * steps
        );
    }

    println!();
    println!("Fish with minds (the Reef demo: perception with occlusion, mind, behaviour, body):");
    println!(
        "{:>7} | {:>10} | {:>10} | {:>14} | {:>19}",
        "animals", "body", "steps/s", "fish-steps/s", "× real time (1/Δt)"
    );
    for body in [ReefBodyKind::Physical, ReefBodyKind::PointMass] {
        for animals in cases(&[10u32, 50, 200]) {
            if only.is_some() {
                break;
            }
            let mut settings = Settings {
                scene: Scene::Reef,
                ..Settings::default()
            };
            Scene::Reef.class().set_animal_count(&mut settings, animals);
            settings.reef.body = body;
            let mut lab = Lab::new(settings);
            lab.step(warm_up(20) as u32);
            let steps_per_sec = rate(Duration::from_secs(3), || lab.step(1));
            println!(
                "{animals:>7} | {:>10} | {steps_per_sec:>10.1} | {:>14.0} | {:>19.2}",
                match body {
                    ReefBodyKind::Physical => "muscles",
                    ReefBodyKind::PointMass => "points",
                },
                steps_per_sec * f64::from(animals),
                steps_per_sec * lab.step_secs()
            );
        }
    }
}
