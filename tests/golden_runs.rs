//! Golden runs: every scene, driven through the public API as `window.shoal` drives
//! it, for a fixed number of steps from a fixed seed; a fingerprint of every
//! animal's state (positions, velocities, every node of a muscle body, hunger,
//! libido and fear, food, catches, the learner's annealing) must equal the one
//! recorded in `tests/golden_runs.txt`.
//!
//! Their purpose: a change meant to move code without changing behaviour (the
//! scene-interface redesign) must leave every fingerprint as it is. A change meant
//! to change behaviour re-records them, in its own commit, saying why:
//!
//! ```text
//! SHOAL_WRITE_GOLDEN=1 cargo test --test golden_runs
//! ```
//!
//! The fingerprint is an FNV-1a hash of the exact bits of the numbers, so it holds
//! on one platform and compiler; the runs are the same in the debug and release
//! profiles (checked when recorded).

use glam::Vec3;
use serde_json::json;
use shoal::automation::Command;
use shoal::lab::Lab;
use shoal::settings::Settings;
use shoal::sim::reef::world::ReefBody;

/// FNV-1a, 64 bits, over the bits of the numbers fed to it.
struct Fingerprint(u64);

impl Fingerprint {
    fn new() -> Self {
        Self(0xcbf2_9ce4_8422_2325)
    }

    fn bytes(&mut self, bytes: &[u8]) {
        for b in bytes {
            self.0 ^= u64::from(*b);
            self.0 = self.0.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }

    fn f32(&mut self, x: f32) {
        self.bytes(&x.to_bits().to_le_bytes());
    }

    fn f64(&mut self, x: f64) {
        self.bytes(&x.to_bits().to_le_bytes());
    }

    fn u64(&mut self, x: u64) {
        self.bytes(&x.to_le_bytes());
    }

    fn vec3(&mut self, v: Vec3) {
        for x in v.to_array() {
            self.f32(x);
        }
    }
}

/// The fingerprint of every run of the lab (one, or two when comparing).
fn fingerprint(lab: &Lab) -> u64 {
    let mut h = Fingerprint::new();
    for run in lab.runs() {
        h.f64(run.time_secs());
        h.u64(run.steps());
        if let Some(physics) = run.scene().physics() {
            for a in physics.animals() {
                for p in a.nodes_m() {
                    h.vec3(p);
                }
                h.vec3(a.point.velocity_m_per_s);
            }
        } else if let Some(reef) = run.scene().reef() {
            for a in reef.animals() {
                h.u64(u64::from(a.alive));
                h.vec3(a.body.position_m());
                h.vec3(a.body.velocity_m_per_s());
                if let ReefBody::Physical(p) = &a.body {
                    for n in p.nodes_m() {
                        h.vec3(n);
                    }
                }
                h.f32(a.mental.hunger);
                h.f32(a.mental.libido);
                h.f32(a.mental.fear);
            }
            for f in reef.food() {
                h.vec3(f.position_m);
            }
            let c = reef.counts();
            for n in [c.prey_eaten, c.missed_strikes, c.food_eaten, c.spawnings] {
                h.u64(u64::from(n));
            }
        } else if let Some(learning) = run.scene().learning() {
            for p in learning.demo_nodes_m() {
                h.vec3(p);
            }
            h.u64(learning.annealing_steps());
            h.f32(learning.progress());
        } else if let Some(world) = run.scene().boids() {
            for f in world.fish() {
                h.vec3(f.position_m);
                h.vec3(f.velocity_m_per_s);
            }
            for s in world.sharks() {
                h.vec3(s.body.position_m);
                h.vec3(s.body.velocity_m_per_s);
            }
            for s in world.stingrays() {
                h.vec3(s.body.position_m);
                h.vec3(s.body.velocity_m_per_s);
            }
            h.u64(world.catches());
        }
    }
    h.0
}

/// A recorded run: set `settings`, then step `steps` times.
fn case(name: &str, settings: serde_json::Value, steps: u32) -> (String, Vec<Command>) {
    (
        name.to_string(),
        vec![Command::Set(settings), Command::Step(steps)],
    )
}

/// The recorded runs: a name and the commands that make it.
fn cases() -> Vec<(String, Vec<Command>)> {
    let mut cases = vec![
        case("aquarium", json!({"scene": "aquarium", "seed": 3}), 200),
        case("boids", json!({"scene": "boids", "seed": 3}), 200),
        case(
            "boids-monte-carlo-sharks-stingrays",
            json!({"scene": "boids", "seed": 4,
                "left": {"mode": "monte_carlo", "sharks": 1, "stingrays": 1}}),
            150,
        ),
        case(
            "boids-compare",
            json!({"scene": "boids", "seed": 5, "compare": true}),
            150,
        ),
        case("physics-school", json!({"scene": "physics", "seed": 5}), 60),
        case(
            "physics-wander",
            json!({"scene": "physics", "seed": 6, "physics": {"behaviour": "wander"}}),
            60,
        ),
    ];
    let (name, mut learning) = case("learning", json!({"scene": "learning", "seed": 1}), 60);
    learning.push(Command::Train(20));
    cases.push((name, learning));
    for demo in [
        "reef",
        "predator_and_school",
        "courtship",
        "feeding",
        "school_meets_obstacle",
    ] {
        for body in ["physical", "point_mass"] {
            cases.push(case(
                &format!("reef-{demo}-{body}"),
                json!({"scene": "reef", "seed": 2, "reef": {"demo": demo, "body": body}}),
                60,
            ));
        }
    }
    cases
}

fn run_case(commands: Vec<Command>) -> u64 {
    let mut lab = Lab::new(Settings::default());
    for c in commands {
        c.execute(&mut lab).expect("a valid command");
    }
    for run in lab.runs() {
        assert!(run.steps() > 0, "the run stepped");
    }
    fingerprint(&lab)
}

const RECORD: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/golden_runs.txt");

#[test]
fn every_scene_runs_as_recorded() {
    let measured: Vec<(String, u64)> = cases()
        .into_iter()
        .map(|(name, commands)| (name, run_case(commands)))
        .collect();
    if std::env::var("SHOAL_WRITE_GOLDEN").is_ok() {
        let mut text = String::from(
            "# Golden runs (tests/golden_runs.rs): name and fingerprint.\n\
             # Re-record only for a change meant to change behaviour:\n\
             # SHOAL_WRITE_GOLDEN=1 cargo test --test golden_runs\n",
        );
        for (name, hash) in &measured {
            text.push_str(&format!("{name} {hash:016x}\n"));
        }
        std::fs::write(RECORD, text).expect("writes the record");
        return;
    }
    let recorded = std::fs::read_to_string(RECORD).expect("tests/golden_runs.txt");
    let expected: Vec<(String, u64)> = recorded
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let (name, hash) = l.split_once(' ').expect("name and hash");
            (
                name.to_string(),
                u64::from_str_radix(hash.trim(), 16).expect("hex"),
            )
        })
        .collect();
    let names = |v: &[(String, u64)]| v.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
    assert_eq!(names(&measured), names(&expected), "the recorded cases");
    let changed: Vec<&str> = measured
        .iter()
        .zip(&expected)
        .filter(|(m, e)| m.1 != e.1)
        .map(|(m, _)| m.0.as_str())
        .collect();
    assert!(
        changed.is_empty(),
        "these runs no longer run as recorded: {changed:?} (if the change was meant to \
         change behaviour, re-record with SHOAL_WRITE_GOLDEN=1 and say why)"
    );
}

#[test]
fn a_run_repeats_exactly() {
    // The fingerprint is a function of the commands: the same case twice gives
    // the same value, and a different seed a different one.
    let feeding = |seed: u64| {
        case(
            "feeding",
            json!({"scene": "reef", "seed": seed, "reef": {"demo": "feeding"}}),
            30,
        )
        .1
    };
    assert_eq!(run_case(feeding(2)), run_case(feeding(2)));
    assert_ne!(run_case(feeding(2)), run_case(feeding(3)));
}
