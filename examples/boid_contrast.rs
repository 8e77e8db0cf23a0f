//! Does the schooling contrast hold wherever a teacher moves the sliders? Runs
//! Table 1's *Individual* and *Group* weights (blended, the same senses and body
//! in both) at every school size the *Fish* slider's marks offer, on seeds no
//! test or tuning uses, and prints, per size and preset, the mean and the worst
//! seed of each window: the figures `docs/boids.md` quotes.
//!
//! ```sh
//! cargo run --release --example boid_contrast                 # the full sweep
//! cargo run --release --example boid_contrast -- --sizes 20,200 --seeds 31-40 --secs 120
//! cargo run --release --example boid_contrast -- --mode classic
//! cargo run --release --example boid_contrast -- --ablate far_field
//! cargo run --release --example boid_contrast -- --sharks 1 --ablate fear   # a fright's weights
//! ```
//!
//! Windows: 20–60 s and 60–120 s; with `--secs 300`, also 240–300 s. Metrics are
//! sampled four times a second, as the app's plots are.

use shoal::sim::boids::control_mode::{ControlMode, GROUP_WEIGHTS, INDIVIDUAL_WEIGHTS};
use shoal::sim::{BoidParams, World, WorldConfig};
use std::thread;

/// The measuring windows, seconds.
const WINDOWS: [(f64, f64); 3] = [(20.0, 60.0), (60.0, 120.0), (240.0, 300.0)];

#[derive(Clone, Copy, Default)]
struct Sample {
    polarization: f64,
    milling: f64,
    nnd: f64,
    groups: f64,
    speed: f64,
}

impl Sample {
    fn add(&mut self, o: &Sample, k: f64) {
        self.polarization += o.polarization * k;
        self.milling += o.milling * k;
        self.nnd += o.nnd * k;
        self.groups += o.groups * k;
        self.speed += o.speed * k;
    }
}

struct Options {
    sizes: Vec<usize>,
    seeds: Vec<u64>,
    secs: f64,
    mode: ControlMode,
    ablate: Vec<String>,
    threads: usize,
    presets: Vec<&'static str>,
    /// `--weights c,a,co,s,av`: these weights instead of the presets' (a probe).
    weights: Option<[f32; 5]>,
    wander: Option<f32>,
    vision: Option<f32>,
    k: Option<usize>,
    /// `--sharks N`: N sharks hunt the school (default 0, the contrast's tank);
    /// the catches are then printed per preset.
    sharks: usize,
    /// `--depth`: also print how much the fish use the tank's height (the
    /// SIMBA papers' school is flat).
    depth: bool,
}

fn parse() -> Options {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1))
            .cloned()
    };
    let list = |s: String| -> Vec<u64> {
        s.split(',')
            .flat_map(|part| match part.split_once('-') {
                Some((a, b)) => (a.parse().expect("a seed or size")
                    ..=b.parse().expect("a seed or size"))
                    .collect::<Vec<u64>>(),
                None => vec![part.parse().expect("a seed or size")],
            })
            .collect()
    };
    Options {
        sizes: value("--sizes").map_or(vec![20, 50, 200, 1000, 2000], |s| {
            list(s).into_iter().map(|n| n as usize).collect()
        }),
        seeds: value("--seeds").map_or((31..=50).collect(), list),
        secs: value("--secs").map_or(120.0, |s| s.parse().expect("a number")),
        mode: match value("--mode").as_deref() {
            Some("classic") => ControlMode::Classic,
            Some("alternate") => ControlMode::DirectAlternate,
            Some("monte_carlo") => ControlMode::MonteCarlo,
            _ => ControlMode::Blended,
        },
        ablate: value("--ablate").map_or(vec![], |s| s.split(',').map(str::to_owned).collect()),
        threads: value("--threads").map_or(1, |s| s.parse().expect("a number")),
        weights: value("--weights").map(|s| {
            let w: Vec<f32> = s.split(',').map(|x| x.parse().expect("a weight")).collect();
            [w[0], w[1], w[2], w[3], w[4]]
        }),
        wander: value("--wander").map(|s| s.parse().expect("a number")),
        vision: value("--vision").map(|s| s.parse().expect("a number")),
        k: value("--k").map(|s| s.parse().expect("a number")),
        depth: args.iter().any(|a| a == "--depth"),
        sharks: value("--sharks").map_or(0, |s| s.parse().expect("a number")),
        presets: match value("--presets").as_deref() {
            Some("group") => vec!["Group"],
            Some("individual") => vec!["Individual"],
            Some("paper") => vec!["Monte Carlo (paper)"],
            _ => vec!["Individual", "Group"],
        },
    }
}

fn params(preset: &str, mode: ControlMode) -> BoidParams {
    let group = BoidParams::group();
    match preset {
        "Individual" => BoidParams {
            weights: INDIVIDUAL_WEIGHTS,
            mode,
            ..group
        },
        "Group" => BoidParams {
            weights: GROUP_WEIGHTS,
            mode,
            ..group
        },
        _ => BoidParams {
            weights: shoal::sim::boids::control_mode::MONTE_CARLO_PAPER_WEIGHTS
                .map(|w| w * 100.0 / 3.2),
            mode: ControlMode::MonteCarlo,
            ..group
        },
    }
}

/// One run: the mean of each window, the share of fish-steps with a
/// neighbour closer than half a body length, the sharks' catches, and (after
/// 20 s) the mean vertical share of the speed, the mean vertical spread of the
/// fish (standard deviation of their heights, m) and the polarization of their
/// level headings alone.
fn run(
    fish: usize,
    seed: u64,
    p: BoidParams,
    o: &Options,
) -> (Vec<Sample>, [f64; 3], u64, [f64; 3]) {
    let mut world = World::new(WorldConfig {
        seed,
        fish_count: fish,
        sharks: o.sharks,
        ..WorldConfig::default()
    });
    let mut p = p;
    for what in &o.ablate {
        match what.as_str() {
            // Every heeded neighbour's heading read in full.
            "clear_sight" => p.perception.clear_sight_m = f32::INFINITY,
            "far_field" => p.perception.far_pull = 0.0,
            "speed_floor" => p.perception.min_speed_m_per_s = 0.0,
            "fear" => {
                let w = world.world_params_mut();
                w.fear_cohesion_factor = 1.0;
                w.fear_separation_factor = 1.0;
            }
            other => panic!("unknown ablation {other}"),
        }
    }
    if let Some(k) = o.k {
        world.world_params_mut().steering.topological_neighbours = k;
    }
    world.set_boids(Some(p));
    let steps = (o.secs * 60.0).round() as u64;
    let mut sums = vec![Sample::default(); WINDOWS.len()];
    let mut counts = vec![0.0; WINDOWS.len()];
    let (mut close, mut fish_samples, mut at_edge, mut in_zone) = (0u64, 0u64, 0u64, 0u64);
    let (mut vertical, mut spread, mut level_pol, mut snapshots) = (0.0, 0.0, 0.0, 0.0);
    for step in 1..=steps {
        world.step();
        if step % 15 != 0 {
            continue;
        }
        let t = step as f64 / 60.0;
        let m = world.metrics().school;
        let s = Sample {
            polarization: f64::from(m.polarization),
            milling: f64::from(m.milling),
            nnd: f64::from(m.nnd_body_lengths),
            groups: f64::from(m.groups),
            speed: f64::from(m.mean_speed_m_per_s),
        };
        for (w, &(a, b)) in WINDOWS.iter().enumerate() {
            if t > a && t <= b {
                sums[w].add(&s, 1.0);
                counts[w] += 1.0;
            }
        }
        if t > 20.0 && step % 60 == 0 {
            let f = world.fish();
            let tank = *world.tank();
            if o.depth && !f.is_empty() {
                let n = f.len() as f64;
                let mean_y = f.iter().map(|a| f64::from(a.position_m.y)).sum::<f64>() / n;
                let var_y = f
                    .iter()
                    .map(|a| {
                        let dy = f64::from(a.position_m.y) - mean_y;
                        dy * dy
                    })
                    .sum::<f64>()
                    / n;
                let mut level = glam::DVec2::ZERO;
                for a in f {
                    let v = a.velocity_m_per_s.as_dvec3();
                    vertical += v.y.abs() / v.length().max(1e-9) / n;
                    level += glam::DVec2::new(v.x, v.z).normalize_or_zero() / n;
                }
                spread += var_y.sqrt();
                level_pol += level.length();
                snapshots += 1.0;
            }
            for (i, a) in f.iter().enumerate() {
                let p = a.position_m;
                let gap_m = (p - tank.min_m).min(tank.max_m - p).min_element();
                at_edge += u64::from(gap_m < 0.1);
                in_zone += u64::from(gap_m < 1.0);
                fish_samples += 1;
                let half = 0.5 * a.body_length_m;
                close += u64::from(f.iter().enumerate().any(|(j, b)| {
                    j != i && a.position_m.distance_squared(b.position_m) < half * half
                }));
            }
        }
    }
    let means = sums
        .iter()
        .zip(&counts)
        .map(|(s, &c)| {
            let mut m = Sample::default();
            if c > 0.0 {
                m.add(s, 1.0 / c);
            }
            m
        })
        .collect();
    let pct = |n: u64| n as f64 * 100.0 / fish_samples.max(1) as f64;
    let per = |x: f64| x / f64::max(snapshots, 1.0);
    (
        means,
        [pct(close), pct(at_edge), pct(in_zone)],
        world.catches(),
        [per(vertical), per(spread), per(level_pol)],
    )
}

fn main() {
    let o = parse();
    println!(
        "mode {:?}, seeds {:?}, {} s{}\n",
        o.mode,
        o.seeds,
        o.secs,
        if o.ablate.is_empty() {
            String::new()
        } else {
            format!(", ablated: {}", o.ablate.join(", "))
        }
    );
    println!(
        "| fish | preset | window (s) | polarization mean | worst seed | milling | NND (BL) | groups (mean / most) | speed (m/s) | neighbour < ½ BL (% fish-samples) |"
    );
    println!("| ---: | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    for &fish in &o.sizes {
        for &preset in &o.presets {
            let mut p = params(preset, o.mode);
            if let Some(w) = o.weights {
                p.weights = w;
            }
            if let Some(w) = o.wander {
                p.wander_weight = w;
            }
            if let Some(v) = o.vision {
                p.perception.vision_distance_m = v;
            }
            let jobs: Vec<u64> = o.seeds.clone();
            type Run = (u64, Vec<Sample>, [f64; 3], u64, [f64; 3]);
            let results: Vec<Run> = thread::scope(|scope| {
                let chunks: Vec<Vec<u64>> = (0..o.threads)
                    .map(|t| jobs.iter().skip(t).step_by(o.threads).copied().collect())
                    .collect();
                let handles: Vec<_> = chunks
                    .into_iter()
                    .map(|chunk| {
                        let o = &o;
                        scope.spawn(move || {
                            chunk
                                .into_iter()
                                .map(|seed| {
                                    let (s, c, caught, d) = run(fish, seed, p, o);
                                    (seed, s, c, caught, d)
                                })
                                .collect::<Vec<_>>()
                        })
                    })
                    .collect();
                handles
                    .into_iter()
                    .flat_map(|h| h.join().expect("a run finishes"))
                    .collect()
            });
            let k = results.len() as f64;
            for (w, &(a, b)) in WINDOWS.iter().enumerate() {
                if b > o.secs {
                    continue;
                }
                let mut mean = Sample::default();
                let mut worst = (f64::NAN, 0u64);
                let mut most_groups = 0.0f64;
                for (seed, s, ..) in &results {
                    mean.add(&s[w], 1.0 / k);
                    let bad = if preset == "Individual" {
                        s[w].polarization > worst.0 || worst.0.is_nan()
                    } else {
                        s[w].polarization < worst.0 || worst.0.is_nan()
                    };
                    if bad {
                        worst = (s[w].polarization, *seed);
                    }
                    most_groups = most_groups.max(s[w].groups);
                }
                let share = |m: usize| results.iter().map(|r| r.2[m]).sum::<f64>() / k;
                let (close, edge, zone) = (share(0), share(1), share(2));
                println!(
                    "| {fish} | {preset} | {a}–{b} | {:.2} | {:.2} (seed {}) | {:.2} | {:.2} | {:.1} / {:.1} | {:.2} | {:.2} | {:.2} | {:.1} |",
                    mean.polarization,
                    worst.0,
                    worst.1,
                    mean.milling,
                    mean.nnd,
                    mean.groups,
                    most_groups,
                    mean.speed,
                    close,
                    edge,
                    zone
                );
            }
            if o.depth {
                let d = |m: usize| results.iter().map(|r| r.4[m]).sum::<f64>() / k;
                println!(
                    "| {fish} | {preset} | after 20 s | vertical share of speed {:.3} | height spread {:.2} m | level-heading polarization {:.2} |",
                    d(0),
                    d(1),
                    d(2)
                );
            }
            if o.sharks > 0 {
                let caught: Vec<u64> = results.iter().map(|r| r.3).collect();
                println!(
                    "| {fish} | {preset} | catches in {} s, per seed | {caught:?} (mean {:.1}) |",
                    o.secs,
                    caught.iter().sum::<u64>() as f64 / k
                );
            }
        }
    }
}
