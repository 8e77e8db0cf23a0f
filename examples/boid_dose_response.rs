//! Measures what each urge slider of the schooling lab does: the tables and the
//! figure of `docs/boids.md`.
//!
//! ```sh
//! cargo run --example boid_dose_response            # prints Markdown tables
//! cargo run --example boid_dose_response -- --svg docs/boids-dose-response.svg
//! ```
//!
//! Every run: the default tank (seeded rocks and pillars), 200 fish, 60 simulated
//! seconds; the metrics are averaged over the last 30 s (sampled four times a
//! second) and then over the seeds. Each dose varies one weight from the *Group*
//! preset's values, everything else as the app's defaults.

use shoal::sim::boids::control_mode::{ControlMode, GROUP_WEIGHTS, INDIVIDUAL_WEIGHTS};
use shoal::sim::{BoidParams, World, WorldConfig};

/// Seeds of each measurement.
const SEEDS: [u64; 4] = [1, 2, 3, 4];
/// Weight levels of the dose–response curves.
const LEVELS: [f32; 5] = [0.0, 25.0, 50.0, 75.0, 100.0];
const NAMES: [&str; 5] = [
    "containment",
    "alignment",
    "cohesion",
    "separation",
    "avoidance",
];

/// Averages of one configuration over the seeds.
#[derive(Clone, Copy, Default)]
struct Outcome {
    polarization: f64,
    milling: f64,
    nnd_body_lengths: f64,
    groups: f64,
    speed_m_per_s: f64,
    /// Percent of fish-steps within 0.1 m of the glass, sand or surface.
    edge_percent: f64,
    /// Percent of fish-steps within 0.1 m of a rock, pillar or ledge.
    rock_percent: f64,
    /// Percent of fish-steps within 1 m of the glass, sand or surface (the
    /// pond's edge zone, which containment keeps fish out of).
    edge_zone_percent: f64,
}

fn run(params: BoidParams) -> Outcome {
    let mut mean = Outcome::default();
    for &seed in &SEEDS {
        let mut world = World::new(WorldConfig {
            seed,
            fish_count: 200,
            ..WorldConfig::default()
        });
        world.set_boids(Some(params));
        let steps = 3600u64;
        let (mut samples, mut fish_steps, mut edge, mut rock, mut zone) =
            (0.0, 0u64, 0u64, 0u64, 0u64);
        let mut sum = Outcome::default();
        for step in 1..=steps {
            world.step();
            if step <= steps / 2 {
                continue;
            }
            let tank = *world.tank();
            for fish in world.fish() {
                let p = fish.position_m;
                let gap_m = (p - tank.min_m).min(tank.max_m - p).min_element();
                edge += u64::from(gap_m < 0.1);
                zone += u64::from(gap_m < 1.0);
                rock += u64::from(
                    world
                        .obstacles()
                        .iter()
                        .any(|o| o.signed_distance_m(p) < 0.1),
                );
                fish_steps += 1;
            }
            if step % 15 == 0 {
                let m = world.metrics().school;
                sum.polarization += f64::from(m.polarization);
                sum.milling += f64::from(m.milling);
                sum.nnd_body_lengths += f64::from(m.nnd_body_lengths);
                sum.groups += f64::from(m.groups);
                sum.speed_m_per_s += f64::from(m.mean_speed_m_per_s);
                samples += 1.0;
            }
        }
        let k = SEEDS.len() as f64;
        mean.polarization += sum.polarization / samples / k;
        mean.milling += sum.milling / samples / k;
        mean.nnd_body_lengths += sum.nnd_body_lengths / samples / k;
        mean.groups += sum.groups / samples / k;
        mean.speed_m_per_s += sum.speed_m_per_s / samples / k;
        mean.edge_percent += edge as f64 / fish_steps as f64 * 100.0 / k;
        mean.rock_percent += rock as f64 / fish_steps as f64 * 100.0 / k;
        mean.edge_zone_percent += zone as f64 / fish_steps as f64 * 100.0 / k;
    }
    mean
}

fn row(label: &str, o: &Outcome) -> String {
    format!(
        "| {label} | {:.2} | {:.2} | {:.2} | {:.1} | {:.2} | {:.2} | {:.1} | {:.2} |",
        o.polarization,
        o.milling,
        o.nnd_body_lengths,
        o.groups,
        o.speed_m_per_s,
        o.edge_percent,
        o.edge_zone_percent,
        o.rock_percent
    )
}

const HEADER: &str = "| configuration | polarization | milling | NND (body lengths) | groups | speed (m/s) | within 0.1 m of the glass, sand or surface (% of fish-steps) | within 1 m of them (%) | within 0.1 m of a rock (%) |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |";

fn main() {
    let svg_path = std::env::args().skip_while(|a| a != "--svg").nth(1);
    let group = BoidParams::group();
    let individual = BoidParams::individual();

    println!("## Presets and modes (weights alone; seeds 1–4)\n\n{HEADER}");
    for mode in ControlMode::ALL {
        for (name, weights) in [("Group", GROUP_WEIGHTS), ("Individual", INDIVIDUAL_WEIGHTS)] {
            let o = run(BoidParams {
                weights,
                mode,
                ..group
            });
            println!("{}", row(&format!("{name}, {mode:?}"), &o));
        }
    }
    let paper = BoidParams {
        weights: shoal::sim::boids::control_mode::MONTE_CARLO_PAPER_WEIGHTS
            .map(|w| w * 100.0 / 3.2),
        mode: ControlMode::MonteCarlo,
        ..group
    };
    println!("{}", row("Monte Carlo (paper) preset", &run(paper)));
    println!(
        "{}",
        row(
            "Individual weights, wander 0",
            &run(BoidParams {
                wander_weight: 0.0,
                ..individual
            })
        )
    );
    println!(
        "{}",
        row(
            "Group weights, wander 0",
            &run(BoidParams {
                wander_weight: 0.0,
                ..group
            })
        )
    );

    println!("\n## Dose–response (one weight varied from the Group preset; blended; seeds 1–4)\n");
    let mut curves = Vec::new();
    for (f, name) in NAMES.iter().enumerate() {
        println!("### {name}\n\n{HEADER}");
        let mut curve = Vec::new();
        for level in LEVELS {
            let mut weights = GROUP_WEIGHTS;
            weights[f] = level;
            let o = run(BoidParams { weights, ..group });
            println!("{}", row(&format!("{name} {level}"), &o));
            curve.push(o);
        }
        println!();
        curves.push(curve);
    }
    println!("#### containment, with the Individual weights\n\n{HEADER}");
    for level in [0.0, 18.0, 50.0, 100.0] {
        let mut weights = INDIVIDUAL_WEIGHTS;
        weights[0] = level;
        let o = run(BoidParams {
            weights,
            ..individual
        });
        println!("{}", row(&format!("containment {level}"), &o));
    }
    println!();
    if let Some(path) = svg_path {
        match std::fs::write(&path, svg(&curves)) {
            Ok(()) => println!("wrote {path}"),
            Err(err) => eprintln!("could not write {path}: {err}"),
        }
    }
}

/// A small multiple: one panel per metric (polarization, NND, groups, milling,
/// time near the pond's edges, speed),
/// one line per urge, weight on the x axis.
fn svg(curves: &[Vec<Outcome>]) -> String {
    const COLOURS: [&str; 5] = ["#7f7f7f", "#1f77b4", "#2ca02c", "#d62728", "#9467bd"];
    type Get = fn(&Outcome) -> f64;
    let panels: [(&str, Get, f64); 4] = [
        ("Polarization", |o| o.polarization, 1.0),
        (
            "Nearest neighbour (body lengths)",
            |o| o.nnd_body_lengths,
            2.5,
        ),
        ("Groups", |o| o.groups, 40.0),
        ("Milling", |o| o.milling, 1.0),
    ];
    let (w, h, pad) = (300.0, 210.0, 40.0);
    let mut out = format!(
        "<svg xmlns='http://www.w3.org/2000/svg' width='{}' height='{}' font-family='sans-serif' font-size='11'>\n<rect width='100%' height='100%' fill='white'/>\n",
        w * 3.0 + 40.0,
        h * 2.0 + 50.0
    );
    for (p, (title, get, max)) in panels.iter().enumerate() {
        let (ox, oy) = ((p % 3) as f64 * (w + 20.0), (p / 3) as f64 * h + 10.0);
        let (x0, y0, x1, y1) = (ox + pad, oy + 20.0, ox + w - 10.0, oy + h - 30.0);
        out += &format!(
            "<text x='{}' y='{}' font-weight='bold'>{title}</text>\n",
            x0,
            oy + 12.0
        );
        out += &format!(
            "<rect x='{x0}' y='{y0}' width='{}' height='{}' fill='none' stroke='#444'/>\n",
            x1 - x0,
            y1 - y0
        );
        for t in 0..=4 {
            let v = max * f64::from(t) / 4.0;
            let y = y1 - (y1 - y0) * f64::from(t) / 4.0;
            out += &format!(
                "<text x='{}' y='{}' text-anchor='end'>{}</text><line x1='{x0}' x2='{x1}' y1='{y}' y2='{y}' stroke='#ddd'/>\n",
                x0 - 4.0,
                y + 4.0,
                if *max >= 10.0 {
                    format!("{v:.0}")
                } else {
                    format!("{v:.2}")
                }
            );
        }
        for (i, level) in LEVELS.iter().enumerate() {
            let x = x0 + (x1 - x0) * i as f64 / (LEVELS.len() - 1) as f64;
            out += &format!(
                "<text x='{x}' y='{}' text-anchor='middle'>{level}</text>\n",
                y1 + 14.0
            );
        }
        out += &format!(
            "<text x='{}' y='{}' text-anchor='middle'>weight (0–100)</text>\n",
            (x0 + x1) / 2.0,
            y1 + 27.0
        );
        for (f, curve) in curves.iter().enumerate() {
            let points: Vec<String> = curve
                .iter()
                .enumerate()
                .map(|(i, o)| {
                    let x = x0 + (x1 - x0) * i as f64 / (LEVELS.len() - 1) as f64;
                    let y = y1 - (y1 - y0) * (get(o) / max).clamp(0.0, 1.0);
                    format!("{x:.1},{y:.1}")
                })
                .collect();
            out += &format!(
                "<polyline points='{}' fill='none' stroke='{}' stroke-width='2'/>\n",
                points.join(" "),
                COLOURS[f]
            );
        }
    }
    for (f, name) in NAMES.iter().enumerate() {
        let x = 40.0 + f as f64 * 160.0;
        let y = h * 2.0 + 35.0;
        out += &format!(
            "<line x1='{x}' x2='{}' y1='{y}' y2='{y}' stroke='{}' stroke-width='3'/><text x='{}' y='{}'>{name}</text>\n",
            x + 20.0,
            COLOURS[f],
            x + 25.0,
            y + 4.0
        );
    }
    out + "</svg>\n"
}
