//! This folder's measurement scripts (see [`crate::census`]): the reef runs
//! whose figures the docs quote, and the helpers the reef's tests share with
//! them. Run one with `cargo run --release --bin shoal-census -- NAME`; some
//! read settings from the environment (named in their lines of the table).

use glam::Vec3;

use crate::census::Census;
use crate::sim::common::fmath;
use crate::sim::reef::courtship::Phase;
use crate::sim::reef::demos::ReefScene;
use crate::sim::reef::events::ReefEventKind;
use crate::sim::reef::mind::{FishKind, Intention, Target};
use crate::sim::reef::world::*;

/// The scripts, in the order `shoal-census` lists them.
pub const CENSUSES: &[Census] = &[
    Census {
        name: "feeding",
        about: "Plankton eaten in 60 s of Feeding on muscles and point masses, seeds 3-4 and 1-8 (docs/fish-body.md)",
        run: feeding,
    },
    Census {
        name: "feeding-and-courtship",
        about: "Plankton eaten in 132 s and the first spawning within 5 min, both bodies, seeds 1-8 (docs/fish-mind.md)",
        run: feeding_and_courtship,
    },
    Census {
        name: "predator",
        about: "Prey eaten, schooling against lone, and missed strikes, both bodies, seeds 1-8 (docs/fish-mind.md)",
        run: predator,
    },
    Census {
        name: "predator-points",
        about: "Prey eaten on point masses, schooling against lone, per eight seeds of 1-32 (docs/fish-body.md)",
        run: predator_points,
    },
    Census {
        name: "pillar-trace",
        about: "The pillar school every 3 s (PILLAR_SEED, default 8): mean x, speed, groups, polarization, folded fins",
        run: pillar_trace,
    },
    Census {
        name: "pillar-seeds",
        about: "Which seeds 1-10 of School meets obstacle split at the pillar and join again, 60 and 120 s (docs/fish-body.md)",
        run: pillar_seeds,
    },
    Census {
        name: "fold",
        about: "Folded tail fins in every demo, seeds 1-2, 2 minutes, muscle bodies (docs/fish-body.md)",
        run: fold,
    },
    Census {
        name: "courtship-seeds",
        about: "When Courtship spawns on seeds 1-16: muscles, point masses, muscles at nominal digestion (docs/fish-body.md)",
        run: courtship_seeds,
    },
    Census {
        name: "courtship-memory",
        about: "Courtship on muscles, seeds 21-30: first spawning within 5 min, and the courting fish-steps that steer by a partner seen, remembered or lost (docs/fish-mind.md)",
        run: courtship_memory,
    },
    Census {
        name: "feeding-time-budget",
        about: "Where the Feeding fish's time goes and how their chases end, seeds 1-8 x 132 s (docs/fish-body.md)",
        run: feeding_time_budget,
    },
    Census {
        name: "feeding-variants",
        about: "Feeding on muscles under variants of how food is chosen and chased, seeds 1-8 (docs/fish-body.md, docs/fish-mind.md)",
        run: feeding_variants,
    },
    Census {
        name: "predator-strike",
        about: "Strikes, misses and the crowd round prey in Predator and school (PROBE, SEEDS, SECS, GAIT) (docs/fish-mind.md)",
        run: predator_strike,
    },
    Census {
        name: "reef-collision",
        about: "Fish collisions on muscles in the reef and the predator demo, seeds 1-8 x 60 s (GAIT=1|0)",
        run: reef_collision,
    },
    Census {
        name: "feeding-agility",
        about: "Feeding on muscles under the AGILE variants: plankton by 60 and 132 s, spine range, folds, collisions (docs/fish-body.md)",
        run: feeding_agility,
    },
];

/// A reef of `scene` on `body` bodies from `seed`, otherwise as by default.
pub(super) fn reef(scene: ReefScene, body: ReefBodyKind, seed: u64) -> ReefWorld {
    ReefWorld::new(ReefConfig {
        seed,
        scene,
        body,
        ..ReefConfig::default()
    })
}

/// Steps `w` through `secs` seconds.
pub(super) fn run(w: &mut ReefWorld, secs: f32) {
    for _ in 0..(secs / w.dt_secs()).round() as u32 {
        w.step();
    }
}

/// Plankton eaten by the six hungry fish of the *Feeding* demo in `secs`.
pub(super) fn feeding_rate(body: ReefBodyKind, seed: u64, secs: f32) -> u32 {
    let mut w = reef(ReefScene::Feeding, body, seed);
    run(&mut w, secs);
    w.counts().food_eaten
}

/// Seconds until the first pair of the *Courtship* demo spawns (`None`
/// if not within `secs`), and the last phase any pair reached.
pub(super) fn spawning_secs(
    body: ReefBodyKind,
    seed: u64,
    secs: f32,
) -> (Option<f32>, Option<Phase>) {
    spawning_secs_in(reef(ReefScene::Courtship, body, seed), secs)
}

/// [`spawning_secs`] in a given reef.
pub(super) fn spawning_secs_in(mut w: ReefWorld, secs: f32) -> (Option<f32>, Option<Phase>) {
    let mut furthest = None;
    for _ in 0..(secs / w.dt_secs()).round() as u32 {
        w.step();
        for p in w.pairs() {
            furthest = furthest.max(Some(p.phase as u8));
        }
        if w.counts().spawnings > 0 {
            return (Some(w.time_secs() as f32), Some(Phase::Spawned));
        }
    }
    let phase = furthest.map(|k| {
        [
            Phase::Looping,
            Phase::Circling,
            Phase::Ascending,
            Phase::Nuzzling,
            Phase::Spawned,
        ][k as usize]
    });
    (None, phase)
}

/// Plankton eaten in 60 s of Feeding on muscles and point masses, seeds 3-4 and 1-8.
fn feeding() {
    let (mut m34, mut p34, mut m, mut p) = (0, 0, 0, 0);
    for seed in 1..=8 {
        let a = feeding_rate(ReefBodyKind::Physical, seed, 60.0);
        let b = feeding_rate(ReefBodyKind::PointMass, seed, 60.0);
        if seed == 3 || seed == 4 {
            m34 += a;
            p34 += b;
        }
        m += a;
        p += b;
    }
    println!("feeding seeds 3-4: muscle {m34} points {p34}; seeds 1-8: muscle {m} points {p}");
}

/// Plankton eaten in 132 s and the first spawning within 5 min, both bodies, seeds 1-8.
fn feeding_and_courtship() {
    // `cargo run --release --bin shoal-census -- feeding-and-courtship`
    for seed in 1..=8 {
        let m = feeding_rate(ReefBodyKind::Physical, seed, 132.0);
        let p = feeding_rate(ReefBodyKind::PointMass, seed, 132.0);
        println!("feeding seed {seed}: muscle {m}, point mass {p} plankton in 132 s");
    }
    for seed in 1..=8 {
        let (secs, phase) = spawning_secs(ReefBodyKind::Physical, seed, 300.0);
        let (psecs, pphase) = spawning_secs(ReefBodyKind::PointMass, seed, 300.0);
        println!(
            "courtship seed {seed}: muscle {secs:?} ({phase:?}), point mass {psecs:?} ({pphase:?})"
        );
    }
}

/// Prey eaten in the *Predator and school* demo over `secs`, summed over
/// seeds 1–8, with every prey fish schooling or every one a loner; and
/// the strikes the shark missed.
fn prey_eaten_on(body: ReefBodyKind, schools: bool, secs: f32) -> (u32, u32) {
    prey_eaten_seeds(body, schools, secs, 1..=8)
}

/// [`prey_eaten_on`] over `seeds`.
pub(super) fn prey_eaten_seeds(
    body: ReefBodyKind,
    schools: bool,
    secs: f32,
    seeds: std::ops::RangeInclusive<u64>,
) -> (u32, u32) {
    prey_eaten_with(body, schools, secs, seeds, |_| {})
}

/// [`prey_eaten_seeds`], with `setup` changing each reef before it runs.
pub(super) fn prey_eaten_with(
    body: ReefBodyKind,
    schools: bool,
    secs: f32,
    seeds: impl IntoIterator<Item = u64>,
    setup: impl Fn(&mut ReefWorld),
) -> (u32, u32) {
    let (mut eaten, mut missed) = (0, 0);
    for seed in seeds {
        let mut w = reef(ReefScene::PredatorAndSchool, body, seed);
        setup(&mut w);
        for i in 0..w.animals().len() {
            if w.animals()[i].habits.kind == FishKind::Prey {
                w.animal_mut(i).expect("an animal").habits.schools = schools;
            }
        }
        run(&mut w, secs);
        eaten += w.counts().prey_eaten;
        missed += w.counts().missed_strikes;
    }
    (eaten, missed)
}

/// Prey eaten, schooling against lone, and missed strikes, both bodies, seeds 1-8.
fn predator() {
    // `cargo run --release --bin shoal-census -- predator`
    for (body, secs) in [
        (ReefBodyKind::PointMass, 120.0),
        (ReefBodyKind::Physical, 300.0),
    ] {
        let (schooled, missed_school) = prey_eaten_on(body, true, secs);
        let (lone, missed_lone) = prey_eaten_on(body, false, secs);
        println!(
            "{body:?}, 8 x {secs} s: schooling {schooled}, lone {lone}, missed {missed_school} / {missed_lone}"
        );
    }
}

/// Prey eaten on point masses, schooling against lone, per eight seeds of 1-32.
fn predator_points() {
    for k in 0..4u64 {
        let r = 1 + 8 * k..=8 + 8 * k;
        let s = prey_eaten_seeds(ReefBodyKind::PointMass, true, 120.0, r.clone());
        let l = prey_eaten_seeds(ReefBodyKind::PointMass, false, 120.0, r.clone());
        println!("seeds {r:?}: schooling {s:?}, lone {l:?}");
    }
}

/// Fig. 17: does the muscle-driven school of the *School meets obstacle*
/// demo meet the pillar as one school, split, and join again within
/// `secs`? (one school, split, rejoined)
pub(super) fn pillar_outcome(seed: u64, secs: f32) -> (bool, bool, bool) {
    let mut w = reef(ReefScene::SchoolMeetsObstacle, ReefBodyKind::Physical, seed);
    let (mut before, mut split, mut rejoined) = (false, false, false);
    for step in 0..(secs / w.dt_secs()) as u32 {
        w.step();
        if step % 9 != 0 {
            continue;
        }
        let x = mean_x_m(&w);
        let m = w.school_metrics();
        if x < -2.0 && m.groups == 1 {
            before = true;
        }
        if (-1.0..1.5).contains(&x) && m.groups >= 2 {
            split = before;
        }
        if x > 2.0 && m.groups == 1 && m.polarization > 0.8 {
            rejoined = split;
        }
    }
    (before, split, rejoined)
}

/// The animals' mean x, metres.
fn mean_x_m(w: &ReefWorld) -> f32 {
    w.animals()
        .iter()
        .map(|a| a.body.position_m().x)
        .sum::<f32>()
        / w.animals().len() as f32
}

/// The pillar school's course: `PILLAR_SEED=8 cargo run --release --bin
/// shoal-census -- pillar-trace` prints every 3 s its mean x, speed, groups,
/// polarization and how many fish have a folded tail fin.
fn pillar_trace() {
    let seed = std::env::var("PILLAR_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(8);
    let mut w = reef(ReefScene::SchoolMeetsObstacle, ReefBodyKind::Physical, seed);
    let n = w.animals().len() as f32;
    let every = (3.0 / w.dt_secs()).round() as u32;
    for step in 0..(120.0 / w.dt_secs()) as u32 {
        w.step();
        if step % every != 0 {
            continue;
        }
        let x = mean_x_m(&w);
        let v = w
            .animals()
            .iter()
            .map(|a| a.body.velocity_m_per_s().length())
            .sum::<f32>()
            / n;
        let m = w.school_metrics();
        let folded = w
            .animals()
            .iter()
            .filter(|a| matches!(&a.body, ReefBody::Physical(f) if f.body().tail_fin_folded()))
            .count();
        println!(
            "t {:5.1} s  x {x:5.2} m  speed {v:.3} m/s  groups {}  polarization {:.2} folded {folded}",
            w.time_secs(),
            m.groups,
            m.polarization
        );
    }
}

/// Which seeds 1-10 of School meets obstacle split at the pillar and join again, 60 and 120 s.
fn pillar_seeds() {
    for seed in 1..=10 {
        println!(
            "pillar seed {seed}: 60 s {:?}, 120 s {:?}",
            pillar_outcome(seed, 60.0),
            pillar_outcome(seed, 120.0)
        );
    }
}

/// Share of fish-time (sampled every 9 steps) and number of muscle fish with a
/// folded tail fin in `secs` of `scene`.
pub(super) fn folded_fins(scene: ReefScene, seed: u64, secs: f32) -> (f32, usize, usize) {
    let mut w = reef(scene, ReefBodyKind::Physical, seed);
    let (mut folded, mut total) = (0usize, 0usize);
    let mut ever = vec![false; w.animals().len()];
    for step in 0..(secs / w.dt_secs()) as u32 {
        w.step();
        if step % 9 != 0 {
            continue;
        }
        for (k, a) in w.animals().iter().enumerate() {
            if let ReefBody::Physical(f) = &a.body {
                total += 1;
                if f.body().tail_fin_folded() {
                    folded += 1;
                    ever[k] = true;
                }
            }
        }
    }
    let share = folded as f32 / total.max(1) as f32;
    (share, ever.iter().filter(|e| **e).count(), ever.len())
}

/// `cargo run --release --bin shoal-census -- fold`: folded fins in every
/// demo, two seeds, two minutes.
fn fold() {
    for scene in ReefScene::ALL {
        for seed in 1..=2 {
            let (share, fish, of) = folded_fins(scene, seed, 120.0);
            println!(
                "{scene:?} seed {seed}: folded {:.1} % of fish-time, {fish} of {of} fish ever",
                100.0 * share
            );
        }
    }
}

/// `cargo run --release --bin shoal-census -- courtship-seeds`: when the
/// courtship demo spawns on seeds 1–16, both bodies.
fn courtship_seeds() {
    for seed in 1..=16 {
        let (secs, phase) = spawning_secs(ReefBodyKind::Physical, seed, 300.0);
        let (p, pp) = spawning_secs(ReefBodyKind::PointMass, seed, 300.0);
        let mut nominal = ReefConfig {
            scene: ReefScene::Courtship,
            seed,
            ..ReefConfig::default()
        };
        nominal.traits.pacifist.digestion_rate_per_unit =
            Some(crate::sim::reef::mind::mental_state::NOMINAL_DIGESTION_RATE);
        let (n, np) = spawning_secs_in(ReefWorld::new(nominal), 300.0);
        println!(
            "courtship seed {seed}: muscle {secs:?} ({phase:?}) points {p:?} ({pp:?}) muscle with nominal p0 {n:?} ({np:?})"
        );
    }
}

/// Courtship on muscles, seeds 21–30 (seeds the docs' other courtship figures
/// do not use): when each spawns within 5 minutes, and of the fish-steps in a
/// pair how many follow a partner in view, one remembered (out of view, last
/// seen under [`crate::sim::reef::params::ReefParams::threat_memory_secs`]
/// ago) or one forgotten. `cargo run --release --bin shoal-census --
/// courtship-memory`.
fn courtship_memory() {
    let (mut spawned, mut seen, mut remembered, mut lost) = (0, 0u64, 0u64, 0u64);
    for seed in 21..=30 {
        let mut w = reef(ReefScene::Courtship, ReefBodyKind::Physical, seed);
        let mut first = None;
        for _ in 0..(300.0 / w.dt_secs()).round() as u32 {
            w.step();
            for pair in w.pairs() {
                for (me, other) in [(pair.male, pair.female), (pair.female, pair.male)] {
                    match w.animals()[me as usize].last_mate {
                        Some((j, _, left)) if j == other => {
                            if left >= w.params().threat_memory_secs {
                                seen += 1;
                            } else {
                                remembered += 1;
                            }
                        }
                        _ => lost += 1,
                    }
                }
            }
            if first.is_none() && w.counts().spawnings > 0 {
                first = Some(w.time_secs());
                break;
            }
        }
        spawned += u32::from(first.is_some());
        println!("courtship seed {seed}: first spawning {first:?} s");
    }
    let all = (seen + remembered + lost).max(1) as f64;
    println!(
        "spawned on {spawned} of 10 seeds; courting fish-steps: partner in view {:.1} %, remembered {:.1} %, forgotten {:.1} %",
        100.0 * seen as f64 / all,
        100.0 * remembered as f64 / all,
        100.0 * lost as f64 / all
    );
}

/// Where the *Feeding* fish's time goes, for issue 13: each fish-step of
/// seeds 1–8 × 132 s in one of: mouth open at the food; chasing food at a
/// level bearing under 30°, 30–90°, 90° or more; chasing food more than 25°
/// above or below; eating with no food in view; anything else (avoiding…).
/// Then the chases: how many ended in a meal, were switched for other food,
/// or lost the food to another fish or the sand, with their mean length and
/// the mean distance at which they started. `cargo run --release --bin
/// shoal-census -- feeding-time-budget`.
fn feeding_time_budget() {
    for body in [ReefBodyKind::Physical, ReefBodyKind::PointMass] {
        let mut bins = [0u64; 7];
        let mut starts = [0u64; 5];
        let mut behind_by_start = [0u64; 5];
        let (mut speed_sum, mut chase_steps) = (0.0f64, 0u64);
        let (mut eaten, mut switched, mut lost) = (0u32, 0u32, 0u32);
        let (mut meal_secs, mut meal_start_m) = (0.0f64, 0.0f64);
        let mut eaten_total = 0;
        for seed in 1..=8 {
            let mut w = reef(ReefScene::Feeding, body, seed);
            if body == ReefBodyKind::Physical {
                agile_tweaks(&mut w, &agile_one());
            }
            let n = w.animals().len();
            // Per fish: the food chased, since when, from how far.
            let mut chase: Vec<Option<(u32, f64, f32, usize)>> = vec![None; n];
            // (fish, food) of every meal.
            let mut meals: Vec<(usize, u32)> = Vec::new();
            for _ in 0..(132.0 / w.dt_secs()).round() as u32 {
                let logged = w.events_logged();
                w.step();
                let t = w.time_secs();
                let new = (w.events_logged() - logged) as usize;
                let ate: Vec<usize> = w
                    .events()
                    .iter()
                    .rev()
                    .take(new)
                    .filter_map(|e| match e.kind {
                        ReefEventKind::AteFood { fish } => Some(fish as usize),
                        _ => None,
                    })
                    .collect();
                for &i in &ate {
                    if let Some(Target::Food(id)) = w.animals()[i].focus.target {
                        meals.push((i, id));
                    }
                }
                for (i, slot) in chase.iter_mut().enumerate() {
                    let a = &w.animals()[i];
                    if !a.alive {
                        continue;
                    }
                    let head = a.body.head_m();
                    let target = match (a.focus.intention, a.focus.target) {
                        (Intention::Eat, Some(Target::Food(id))) => Some(id),
                        _ => None,
                    };
                    // How the previous chase ended.
                    if let Some((id, since, from, _)) = *slot
                        && target != Some(id)
                    {
                        let exists = w.food().iter().any(|f| f.id == id);
                        let mine = !exists && meals.contains(&(i, id));
                        if mine {
                            eaten += 1;
                            meal_secs += t - since;
                            meal_start_m += f64::from(from);
                        } else if exists {
                            switched += 1;
                        } else {
                            lost += 1;
                        }
                        *slot = None;
                    }
                    let bin = match (a.focus.intention, a.focus.target) {
                        _ if a.mouth_open => 0,
                        (Intention::Eat, Some(Target::Food(id))) => {
                            let Some(f) = w.food().iter().find(|f| f.id == id) else {
                                continue;
                            };
                            let o = f.position_m - head;
                            let level = Vec3::new(o.x, 0.0, o.z);
                            let h = a.body.heading();
                            let hl = Vec3::new(h.x, 0.0, h.z).normalize_or_zero();
                            let bearing =
                                fmath::acos(hl.dot(level.normalize_or_zero()).clamp(-1.0, 1.0))
                                    .to_degrees();
                            speed_sum += f64::from(a.body.velocity_m_per_s().length());
                            chase_steps += 1;
                            let b = if fmath::atan2(o.y.abs(), level.length()).to_degrees() > 25.0 {
                                4
                            } else if bearing < 30.0 {
                                1
                            } else if bearing < 90.0 {
                                2
                            } else {
                                3
                            };
                            if slot.is_none() {
                                *slot = Some((id, t, f.position_m.distance(head), b));
                                starts[b] += 1;
                            }
                            let started = slot.map_or(0, |c| c.3);
                            if b == 3 {
                                behind_by_start[started] += 1;
                            }
                            b
                        }
                        (Intention::Eat, None) => 5,
                        _ => 6,
                    };
                    bins[bin] += 1;
                }
            }
            eaten_total += w.counts().food_eaten;
        }
        let total = bins.iter().sum::<u64>().max(1) as f64;
        let pct = |k: usize| 100.0 * bins[k] as f64 / total;
        println!(
            "{body:?}: {eaten_total} plankton. Time: mouth open {:.1} %, chasing ahead (<30°) {:.1} %, \
             30-90° {:.1} %, 90°+ {:.1} %, steep (>25°) {:.1} %, no food seen {:.1} %, other {:.1} %; \
             chasing speed {:.3} m/s",
            pct(0),
            pct(1),
            pct(2),
            pct(3),
            pct(4),
            pct(5),
            pct(6),
            speed_sum / chase_steps.max(1) as f64
        );
        println!(
            "  chases: {eaten} ended in a meal (mean {:.1} s from {:.2} m), {switched} switched, {lost} lost",
            meal_secs / f64::from(eaten.max(1)),
            meal_start_m / f64::from(eaten.max(1))
        );
        println!(
            "  chases started ahead / 30-90° / 90°+ / steep: {:?}; steps with the food behind by the chase's start: {:?}",
            &starts[1..],
            &behind_by_start[1..]
        );
    }
}

/// Issue 13, item 5: the *Feeding* demo's muscle fish against variants of the
/// settings that choose and chase their food, seeds 1–8, 60 s and 132 s (point
/// masses: 342 and 723 plankton, ignoring these settings). None moved the
/// muscle fish's count beyond the seeds' spread (about a tenth); the
/// measurements, with the turn-MC variants tried on a patch, are in
/// docs/fish-body.md ("What the converged body changed in the reef"). Also
/// prints the plankton the tank offers: 30 to start with and one particle per
/// 1.5 s while fewer drift. `cargo run --release --bin shoal-census --
/// feeding-variants`.
fn feeding_variants() {
    type Tweak = fn(&mut ReefWorld);
    fn persistence(w: &mut ReefWorld, body_lengths: f32) {
        for k in 0..w.animals().len() {
            if let Some(a) = w.animal_mut(k) {
                a.habits.persistence_body_lengths = body_lengths;
            }
        }
    }
    let variants: [(&str, Tweak); 10] = [
        ("as shipped", |_| {}),
        ("turning path weight 1", |w| {
            w.params_mut().turning_path_weight = 1.0
        }),
        ("persistence 0", |w| persistence(w, 0.0)),
        ("persistence 1", |w| persistence(w, 1.0)),
        ("persistence 5", |w| persistence(w, 5.0)),
        ("turning circle 1.0", |w| {
            w.params_mut().body_turn_radius_body_lengths = 1.0
        }),
        ("turning circle 1.5", |w| {
            w.params_mut().body_turn_radius_body_lengths = 1.5
        }),
        ("climb effort 3", |w| {
            w.params_mut().climb_effort_muscle_body = 3.0
        }),
        ("climb effort 6", |w| {
            w.params_mut().climb_effort_muscle_body = 6.0
        }),
        ("chase pitch 0.5, effort 3", |w| {
            w.params_mut().behaviour.max_food_chase_pitch_rad = 0.5;
            w.params_mut().climb_effort_muscle_body = 3.0;
        }),
    ];
    for (name, tweak) in variants {
        let (mut m60, mut m132) = (0, 0);
        for seed in 1..=8 {
            for (secs, sum) in [(60.0, &mut m60), (132.0, &mut m132)] {
                let mut w = reef(ReefScene::Feeding, ReefBodyKind::Physical, seed);
                tweak(&mut w);
                run(&mut w, secs);
                *sum += w.counts().food_eaten;
            }
        }
        println!("{name:26} muscle: {m60:4} plankton in 60 s, {m132:4} in 132 s");
    }
    let w = reef(ReefScene::Feeding, ReefBodyKind::Physical, 1);
    let offered = |secs: f32| {
        8 * (w.food().len() as u32 + (secs / w.params().food_release_secs).floor() as u32)
    };
    println!(
        "plankton offered over seeds 1-8 at most: {} in 60 s, {} in 132 s",
        offered(60.0),
        offered(132.0)
    );
}

/// What happened at the shark's strikes in *Predator and school*, and how
/// crowded the frightened prey were meanwhile.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct StrikeCensus {
    pub eaten: u32,
    pub missed: u32,
    /// Other prey within the confusion radius of the target, summed over
    /// every strike (eaten or missed).
    pub crowd_at_strikes: u32,
    /// Victims that were escaping (not schooling) when caught.
    pub victims_escaping: u32,
    /// Prey-seconds with fear above 0.5, and their neighbours within the
    /// confusion radius summed over those seconds.
    pub afraid_secs: f32,
    pub afraid_neighbours: f32,
    /// Of the afraid prey-seconds, those spent escaping, and the escaping
    /// prey's neighbours within the confusion radius summed over them.
    pub afraid_escaping_secs: f32,
    pub escaping_neighbours: f32,
}

impl StrikeCensus {
    fn brief(&self) -> String {
        format!(
            "eaten {} missed {} crowd {} | escaping {:.0} s, neighbours {:.0}",
            self.eaten,
            self.missed,
            self.crowd_at_strikes,
            self.afraid_escaping_secs,
            self.escaping_neighbours
        )
    }
}

impl std::ops::AddAssign for StrikeCensus {
    fn add_assign(&mut self, o: Self) {
        self.eaten += o.eaten;
        self.missed += o.missed;
        self.crowd_at_strikes += o.crowd_at_strikes;
        self.victims_escaping += o.victims_escaping;
        self.afraid_secs += o.afraid_secs;
        self.afraid_neighbours += o.afraid_neighbours;
        self.afraid_escaping_secs += o.afraid_escaping_secs;
        self.escaping_neighbours += o.escaping_neighbours;
    }
}

/// [`StrikeCensus`] of one run of *Predator and school*, every prey fish
/// schooling or every one a loner, fleeing schoolmates in the school's gait
/// or not (`BehaviourParams::escape_in_school_gait`).
pub(super) fn strike_census(
    body: ReefBodyKind,
    schools: bool,
    in_school_gait: bool,
    secs: f32,
    seed: u64,
) -> StrikeCensus {
    let mut w = reef(ReefScene::PredatorAndSchool, body, seed);
    w.params_mut().behaviour.escape_in_school_gait = in_school_gait;
    for i in 0..w.animals().len() {
        if w.animals()[i].habits.kind == FishKind::Prey {
            w.animal_mut(i).expect("an animal").habits.schools = schools;
        }
    }
    let crowd_around = |w: &ReefWorld, j: usize, at: Vec3| {
        crate::sim::reef::feeding::prey_crowding(w.params(), w.animals(), j, at) as u32
    };
    let mut c = StrikeCensus::default();
    let dt = w.dt_secs();
    let steps = (secs / dt).round() as u32;
    for _ in 0..steps {
        let before: Vec<Vec3> = w.animals().iter().map(|a| a.body.position_m()).collect();
        let logged = w.events_logged();
        let intentions: Vec<Intention> = w.animals().iter().map(|a| a.focus.intention).collect();
        let crowds: Vec<u32> = (0..w.animals().len())
            .map(|j| crowd_around(&w, j, before[j]))
            .collect();
        w.step();
        let new = (w.events_logged() - logged) as usize;
        let n = w.events().len();
        for e in w.events().iter().skip(n.saturating_sub(new)) {
            match e.kind {
                ReefEventKind::AtePrey { prey, .. } => {
                    c.eaten += 1;
                    c.crowd_at_strikes += crowds[prey as usize];
                    if intentions[prey as usize] == Intention::Escape {
                        c.victims_escaping += 1;
                    }
                }
                ReefEventKind::Missed { crowd, .. } => {
                    c.missed += 1;
                    c.crowd_at_strikes += crowd;
                }
                _ => {}
            }
        }
        for (j, a) in w.animals().iter().enumerate() {
            if a.alive && a.habits.kind == FishKind::Prey && a.mental.fear > 0.5 {
                c.afraid_secs += dt;
                let n = crowd_around(&w, j, a.body.position_m()) as f32;
                c.afraid_neighbours += dt * n;
                if a.focus.intention == Intention::Escape {
                    c.afraid_escaping_secs += dt;
                    c.escaping_neighbours += dt * n;
                }
            }
        }
    }
    c
}

fn strike_census_seeds(
    body: ReefBodyKind,
    schools: bool,
    secs: f32,
    seeds: std::ops::RangeInclusive<u64>,
) -> StrikeCensus {
    let in_school_gait = std::env::var("GAIT").as_deref() != Ok("0");
    let seeds: Vec<u64> = seeds.collect();
    let halves = seeds.split_at(seeds.len() / 2);
    let sum = |seeds: &[u64]| {
        let mut c = StrikeCensus::default();
        for &seed in seeds {
            let one = strike_census(body, schools, in_school_gait, secs, seed);
            if std::env::var("PERSEED").is_ok() {
                println!("  seed {seed} schools={schools}: {}", one.brief());
            }
            c += one;
        }
        c
    };
    let (a, b) = std::thread::scope(|s| {
        let a = s.spawn(|| sum(halves.0));
        let b = sum(halves.1);
        (a.join().expect("the other half's seeds ran"), b)
    });
    let mut c = a;
    c += b;
    c
}

/// Strikes, misses and the crowd round prey in Predator and school.
fn predator_strike() {
    // `PROBE=muscles|points SEEDS=1-8 SECS=300 GAIT=1|0 [PERSEED=1] cargo run
    // --release --bin shoal-census -- predator-strike`: prey eaten, strikes missed, the other prey within the confusion radius of
    // the target at the shark's strikes, and the neighbours of afraid and of
    // escaping prey, with every prey fish schooling and every one a loner.
    // GAIT=0 puts fleeing schoolmates in the swim gait.
    let body = match std::env::var("PROBE").as_deref() {
        Ok("points") => ReefBodyKind::PointMass,
        _ => ReefBodyKind::Physical,
    };
    let seeds = std::env::var("SEEDS").unwrap_or_else(|_| "1-8".into());
    let (a, b) = seeds.split_once('-').expect("SEEDS as FIRST-LAST");
    let seeds = a.parse::<u64>().expect("SEEDS as FIRST-LAST")
        ..=b.parse::<u64>().expect("SEEDS as FIRST-LAST");
    let secs: f32 = std::env::var("SECS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(300.0);
    for schools in [true, false] {
        let c = strike_census_seeds(body, schools, secs, seeds.clone());
        let strikes = (c.eaten + c.missed).max(1) as f32;
        println!(
            "{body:?} schools={schools} seeds {seeds:?} x {secs} s: eaten {} missed {} \
             crowd/strike {:.2} victims escaping {} | afraid {:.0} s, neighbours {:.2}, escaping {:.2} \
             (neighbours {:.2})",
            c.eaten,
            c.missed,
            c.crowd_at_strikes as f32 / strikes,
            c.victims_escaping,
            c.afraid_secs,
            c.afraid_neighbours / c.afraid_secs.max(1e-3),
            c.afraid_escaping_secs / c.afraid_secs.max(1e-3),
            c.escaping_neighbours / c.afraid_escaping_secs.max(1e-3),
        );
    }
}

/// Fish collisions on muscles in the reef and the predator demo, seeds 1-8 x 60 s.
fn reef_collision() {
    // Fish collisions on muscles with fleeing schoolmates in the school's gait
    // or the swim gait (`BehaviourParams::escape_in_school_gait`), seeds 1–8 ×
    // 1 min: `GAIT=1|0 cargo run --release --bin shoal-census -- reef-collision`.
    let gait = std::env::var("GAIT").as_deref() != Ok("0");
    for scene in [ReefScene::Reef, ReefScene::PredatorAndSchool] {
        let mut total = 0;
        for seed in 1..=8 {
            let mut w = reef(scene, ReefBodyKind::Physical, seed);
            w.params_mut().behaviour.escape_in_school_gait = gait;
            run(&mut w, 60.0);
            total += w.counts().fish_collisions;
        }
        println!("{scene:?} gait {gait}: {total} collisions in 8 x 60 s");
    }
}

/// Issue 13, the foraging agility of the muscle body: *Feeding* on muscles
/// (point masses with `AGILE_BODY=point`), seeds 1–`AGILE_SEEDS` (default 8),
/// plankton eaten by 60 s and by 132 s (one run each) and the shortest spine
/// seen, for the variants in `AGILE` ("name:key=value,key=value;name2:…"; keys
/// in [`agile_tweaks`]). `AGILE="shipped:;steep 0.5:finpitch=0.5,trim=0.5,
/// chasepitch=0.44,effort=4" cargo run --release --bin shoal-census --
/// feeding-agility`.
fn feeding_agility() {
    let spec = std::env::var("AGILE").unwrap_or_else(|_| "as shipped:".into());
    let seeds: u64 = std::env::var("AGILE_SEEDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(8);
    for variant in spec.split(';').filter(|v| !v.trim().is_empty()) {
        let (name, keys) = variant.split_once(':').unwrap_or((variant, ""));
        let kv: Vec<(String, f32)> = keys
            .split(',')
            .filter_map(|p| {
                let (k, v) = p.split_once('=')?;
                Some((k.trim().to_string(), v.trim().parse().ok()?))
            })
            .collect();
        let (mut m60, mut m132) = (0, 0);
        let mut per_seed = String::new();
        let (mut spine, mut longest) = (1.0f32, 0.0f32);
        let mut mends = 0;
        let (mut collisions, mut collisions60) = (0, 0);
        let (mut folds, mut blowups) = (0u32, 0u32);
        let started = std::time::Instant::now();
        for seed in 1..=seeds {
            let body = if std::env::var("AGILE_BODY").is_ok_and(|b| b == "point") {
                ReefBodyKind::PointMass
            } else {
                ReefBodyKind::Physical
            };
            let scene = if std::env::var("AGILE_SCENE").is_ok_and(|b| b == "reef") {
                ReefScene::Reef
            } else {
                ReefScene::Feeding
            };
            let mut w = reef(scene, body, seed);
            agile_tweaks(&mut w, &kv);
            let mut shortest = 1.0f32;
            let (mut a, mut c60) = (0, 0);
            let steps60 = (60.0 / w.dt_secs()).round() as u32;
            for step in 0..(132.0 / w.dt_secs()).round() as u32 {
                w.step();
                if step + 1 == steps60 {
                    a = w.counts().food_eaten;
                    c60 = w.counts().fish_collisions;
                }
                if step % 4 == 0 {
                    let tank = *w.tank();
                    for i in 0..w.animals().len() {
                        if let ReefBody::Physical(p) = &w.animals()[i].body {
                            let s = p.body().spine_length_m() / p.body_length_m();
                            shortest = shortest.min(s);
                            longest = longest.max(s);
                            folds += p.body().tail_fin_folded() as u32;
                            let at = w.animals()[i].body.position_m();
                            blowups += (!at.is_finite() || !tank.contains(at, 0.0)) as u32;
                        }
                    }
                }
            }
            let b = w.counts().food_eaten;
            for animal in w.animals() {
                if let ReefBody::Physical(p) = &animal.body {
                    mends += p.body().mends();
                }
            }
            per_seed += &format!(" {a}/{b}");
            collisions += w.counts().fish_collisions;
            collisions60 += c60;
            spine = spine.min(shortest);
            m60 += a;
            m132 += b;
        }
        println!(
            "{name:28} muscle: {m60:4} in 60 s, {m132:4} in 132 s | spine {spine:.2}–{longest:.2} folds {folds} mends {mends} out {blowups} | collisions {collisions60} / {collisions} |{per_seed} ({:.0} s)",
            started.elapsed().as_secs_f32()
        );
    }
}

/// Applies `shoal-census feeding-agility`'s `key=value` tweaks to `w`: `finpitch`
/// (`MotorChoiceParams::forage_max_fin_pitch_rad`), `trim`
/// (`BodyParams::max_trim_rad`), `trimgain` (`BodyParams::fin_trim_gain`),
/// `chasepitch` (`max_food_chase_pitch_rad`),
/// `effort` (`climb_effort_muscle_body`), `radius`
/// (`body_turn_radius_body_lengths`), `pathw` (`turning_path_weight`), `gain`
/// (`course_gain_per_rad`), `cruise` (`cruise_fraction`).
fn agile_tweaks(w: &mut ReefWorld, kv: &[(String, f32)]) {
    for (k, v) in kv {
        let v = *v;
        match k.as_str() {
            "finpitch" => w.params_mut().motor_choice.forage_max_fin_pitch_rad = v,
            "chasepitch" => w.params_mut().behaviour.max_food_chase_pitch_rad = v,
            "effort" => w.params_mut().climb_effort_muscle_body = v,
            "radius" => w.params_mut().body_turn_radius_body_lengths = v,
            "pathw" => w.params_mut().turning_path_weight = v,
            "gain" => w.params_mut().motor_choice.course_gain_per_rad = v,
            "cruise" => w.params_mut().behaviour.cruise_fraction = v,
            "trim" => each_body(w, |b| b.max_trim_rad = v),
            "trimgain" => each_body(w, |b| b.fin_trim_gain = v),
            "trimrate" => each_body(w, |b| b.max_trim_rate_rad_per_s = v),
            "instant" => each_body(w, |b| b.instant_trim_rad = v),
            other => panic!("unknown key {other}"),
        }
    }
}

/// Sets the body parameters of every muscle fish of `w` with `set`.
fn each_body(w: &mut ReefWorld, set: impl Fn(&mut crate::sim::body::BodyParams)) {
    for i in 0..w.animals().len() {
        if let Some(a) = w.animal_mut(i)
            && let ReefBody::Physical(p) = &mut a.body
        {
            set(p.body_mut().params_mut());
        }
    }
}

/// `AGILE_ONE` (`key=value,…`) as tweaks.
fn agile_one() -> Vec<(String, f32)> {
    std::env::var("AGILE_ONE")
        .unwrap_or_default()
        .split(',')
        .filter_map(|p| {
            let (k, v) = p.split_once('=')?;
            Some((k.trim().to_string(), v.trim().parse().ok()?))
        })
        .collect()
}
