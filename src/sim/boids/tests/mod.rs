//! Tests of the boid world, one file per topic (as the avian engine's test
//! files are): placement, determinism, the hard rules, wandering fish, the
//! urges' weights, the control modes, predators, the neighbour stage, the
//! metrics and the attention inspector. The helpers they share are here.

mod attention;
mod control_modes;
mod determinism;
mod hard_rules;
mod metrics;
mod neighbours;
mod placement;
mod predators;
mod urges;
mod wandering;

use glam::Vec3;

use crate::sim::boids::world::{BoidParams, World, WorldConfig};
use crate::sim::common::obstacle::Obstacle;
use crate::sim::common::school_metrics::SchoolMetrics;

fn world(seed: u64, fish_count: usize) -> World {
    World::new(WorldConfig {
        seed,
        fish_count,
        ..WorldConfig::default()
    })
}

fn positions(world: &World) -> Vec<[u32; 3]> {
    let bits = |v: Vec3| [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()];
    world.fish().iter().map(|f| bits(f.position_m)).collect()
}

/// Every fish is finite, in the tank and outside every obstacle.
fn assert_all_fish_legal(world: &World) {
    for (i, fish) in world.fish().iter().enumerate() {
        let (p, v) = (fish.position_m, fish.velocity_m_per_s);
        assert!(
            p.is_finite() && v.is_finite(),
            "fish {i} not finite at step {}",
            world.steps()
        );
        assert!(world.tank().contains(p, 0.0), "fish {i} left the tank: {p}");
        for obstacle in world.obstacles() {
            let gap_m = obstacle.signed_distance_m(p);
            assert!(gap_m >= 0.0, "fish {i} inside {obstacle:?} at {p}");
        }
        for ray in world.stingrays() {
            let gap_m = ray
                .obstacle(world.tank().min_m.y, &world.world_params().stingray)
                .signed_distance_m(p);
            assert!(gap_m >= 0.0, "fish {i} inside a stingray at {p}");
        }
    }
    for shark in world.sharks() {
        let p = shark.body.position_m;
        assert!(p.is_finite() && shark.body.velocity_m_per_s.is_finite());
        assert!(world.tank().contains(p, 0.0), "shark left the tank: {p}");
        for obstacle in world.obstacles() {
            assert!(
                obstacle.signed_distance_m(p) >= 0.0,
                "shark in {obstacle:?}"
            );
        }
    }
    for ray in world.stingrays() {
        let p = ray.body.position_m;
        assert!(p.is_finite() && world.tank().contains(p, 0.0));
        let height_m = p.y - world.tank().min_m.y;
        assert!(
            (0.2 - 1e-4..=0.6 + 1e-4).contains(&height_m),
            "ray at {height_m} m"
        );
    }
}

fn boid_world(params: BoidParams, fish_count: usize) -> World {
    let mut w = World::new(WorldConfig {
        seed: 1,
        fish_count,
        ..WorldConfig::default()
    });
    w.set_boids(Some(params));
    w
}

/// What a class measures of one configuration: the metrics averaged over
/// the last 30 s of a minute (four samples a second) and over `seeds`, and
/// the share of fish-steps within 0.1 m and within 1 m of the glass, sand
/// or surface.
#[derive(Debug, Default)]
struct Measured {
    polarization: f32,
    milling: f32,
    nnd_body_lengths: f32,
    groups: f32,
    speed_m_per_s: f32,
    at_edge: f32,
    in_edge_zone: f32,
    at_rock: f32,
}

fn measure_minute(params: BoidParams, seeds: &[u64]) -> Measured {
    let mut m = Measured::default();
    let k = seeds.len() as f32;
    for &seed in seeds {
        let mut w = World::new(WorldConfig {
            seed,
            fish_count: 200,
            ..WorldConfig::default()
        });
        w.set_boids(Some(params));
        let (mut samples, mut fish_steps, mut edge, mut zone, mut rock) = (0.0, 0.0, 0.0, 0.0, 0.0);
        let mut sum = SchoolMetrics::default();
        for step in 1..=3600 {
            w.step();
            if step <= 1800 {
                continue;
            }
            for f in w.fish() {
                let p = f.position_m;
                let gap_m = (p - w.tank().min_m).min(w.tank().max_m - p).min_element();
                edge += f32::from(gap_m < 0.1);
                zone += f32::from(gap_m < 1.0);
                rock += f32::from(w.obstacles().iter().any(|o| o.signed_distance_m(p) < 0.1));
                fish_steps += 1.0;
            }
            if step % 15 == 0 {
                let s = w.metrics().school;
                sum.polarization += s.polarization;
                sum.milling += s.milling;
                sum.nnd_body_lengths += s.nnd_body_lengths;
                sum.groups += s.groups;
                sum.mean_speed_m_per_s += s.mean_speed_m_per_s;
                samples += 1.0;
            }
        }
        m.polarization += sum.polarization / samples / k;
        m.milling += sum.milling / samples / k;
        m.nnd_body_lengths += sum.nnd_body_lengths / samples / k;
        m.groups += sum.groups as f32 / samples / k;
        m.speed_m_per_s += sum.mean_speed_m_per_s / samples / k;
        m.at_edge += edge / fish_steps / k;
        m.in_edge_zone += zone / fish_steps / k;
        m.at_rock += rock / fish_steps / k;
    }
    m
}

/// The group preset with weight `force` (in `Force::ALL` order) at `level`.
fn group_with(force: usize, level: f32) -> BoidParams {
    let mut params = BoidParams::group();
    params.weights[force] = level;
    params
}

/// The first seed in 0..50 whose generated layout has a reef ledge.
fn seed_with_a_ledge() -> u64 {
    (0..50)
        .find(|&seed| {
            world(seed, 0)
                .obstacles()
                .iter()
                .any(|o| matches!(o, Obstacle::Polygon { .. }))
        })
        .expect("some seed places a ledge")
}
