//! Native benchmark: simulation throughput and the CPU side of a frame.
//!
//! Run with `./dev bench` (or `cargo bench --bench sim_throughput`). Prints figures;
//! asserts nothing. The in-browser counterpart is the `?bench` page mode.

use std::time::{Duration, Instant};

use shoal::lab::Lab;
use shoal::render::{FrameBuilder, OrbitCamera};
use shoal::settings::Settings;
use shoal::sim::{World, WorldConfig};

/// Runs `f` repeatedly for about `budget`, returning calls per second.
fn rate(budget: Duration, mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    let mut calls = 0u64;
    while start.elapsed() < budget {
        f();
        calls += 1;
    }
    calls as f64 / start.elapsed().as_secs_f64()
}

fn main() {
    println!("Shoal native benchmark (one thread)");
    println!(
        "{:>7} | {:>12} | {:>16} | {:>17}",
        "fish", "steps/s", "fish-steps/s", "frame build (ms)"
    );
    for fish_count in [200, 2_000, 5_000, 20_000] {
        let mut world = World::new(WorldConfig {
            seed: 1,
            fish_count,
        });
        for _ in 0..60 {
            world.step();
        }
        let steps_per_sec = rate(Duration::from_secs(2), || world.step());

        let lab = Lab::new(Settings {
            fish_count: fish_count as u32,
            ..Settings::default()
        });
        let tank = lab.world().tank();
        let camera = OrbitCamera::framing(tank.min_m, tank.max_m, 16.0 / 9.0);
        let mut builder = FrameBuilder::default();
        let frames_per_sec = rate(Duration::from_secs(1), || {
            std::hint::black_box(builder.build(&lab, &camera, [1920, 1080], 0.0, 0));
        });
        println!(
            "{fish_count:>7} | {steps_per_sec:>12.0} | {:>16.0} | {:>17.3}",
            steps_per_sec * fish_count as f64,
            1000.0 / frames_per_sec
        );
    }
}
