//! Tests of the reef: every demo, feeding, predation, courtship, schooling round
//! the pillar, on both bodies; and the ignored census runs whose figures the docs
//! quote.

use crate::sim::common::fmath;
use glam::Vec3;

use crate::sim::reef::animal::Seen;
use crate::sim::reef::courtship::Phase;
use crate::sim::reef::demos::ReefScene;
use crate::sim::reef::events::ReefEventKind;
use crate::sim::reef::mind::habits::KindTraits;
use crate::sim::reef::mind::{FishKind, Focus, Habits, Intention, IntentionGenerator, Sex, Target};
use crate::sim::reef::perception::in_a_school;
use crate::sim::reef::world::*;

fn reef(scene: ReefScene, body: ReefBodyKind, seed: u64) -> ReefWorld {
    ReefWorld::new(ReefConfig {
        seed,
        scene,
        body,
        ..ReefConfig::default()
    })
}

/// The (first) predator of a reef.
fn shark_of(w: &ReefWorld) -> usize {
    w.animals()
        .iter()
        .position(|a| a.habits.kind == FishKind::Predator)
        .expect("a predator")
}

fn run(w: &mut ReefWorld, secs: f32) {
    for _ in 0..(secs / w.dt_secs()).round() as u32 {
        w.step();
    }
}

#[test]
fn every_demo_has_valid_rocks_and_starts_everyone_in_the_water() {
    for scene in ReefScene::ALL {
        let w = reef(scene, ReefBodyKind::PointMass, 1);
        for o in w.obstacles() {
            assert_eq!(o.validate(w.tank()), Ok(()), "{scene:?}");
        }
        for a in w.animals() {
            let p = a.body.position_m();
            assert!(w.tank().contains(p, 0.2), "{scene:?} {p}");
            assert!(
                w.obstacles().iter().all(|o| o.signed_distance_m(p) > 0.0),
                "{scene:?}"
            );
        }
        let prey = w
            .animals()
            .iter()
            .filter(|a| a.habits.kind == FishKind::Prey)
            .count();
        assert_eq!(prey, scene.default_prey_count(), "{scene:?}");
        assert_eq!(w.animals().len(), scene.animal_count(prey), "{scene:?}");
        assert_eq!(w.food().len(), scene.default_food_count(), "{scene:?}");
    }
}

#[test]
fn same_seed_same_reef() {
    for body in [ReefBodyKind::PointMass, ReefBodyKind::Physical] {
        let go = || {
            let mut w = reef(ReefScene::Reef, body, 5);
            run(&mut w, 5.0);
            w.animals()
                .iter()
                .map(|a| a.body.position_m().to_array().map(f32::to_bits))
                .collect::<Vec<_>>()
        };
        assert_eq!(go(), go(), "{body:?}");
    }
}

#[test]
fn a_long_reef_run_stays_finite_in_the_tank_and_out_of_rocks() {
    // Collisions are counted over three seeds for each body: one seed's count
    // varies a lot from seed to seed (point masses, 3 minutes, seeds 1–6:
    // 0.56–1.26 starts per animal per minute; muscle bodies, 1 minute, seeds
    // 1–4: 0.44–1.44, since the simulation's sin and cos became libm's).
    let (mut collisions, mut animal_minutes) = (0.0f32, 0.0f32);
    let (mut body_collisions, mut body_minutes) = (0.0f32, 0.0f32);
    for (body, secs, seed) in [
        (ReefBodyKind::PointMass, 180.0, 1),
        (ReefBodyKind::PointMass, 180.0, 2),
        (ReefBodyKind::PointMass, 180.0, 3),
        (ReefBodyKind::Physical, 60.0, 1),
        (ReefBodyKind::Physical, 60.0, 2),
        (ReefBodyKind::Physical, 60.0, 3),
    ] {
        let mut w = reef(ReefScene::Reef, body, seed);
        let tank = *w.tank();
        let steps = (secs / w.dt_secs()) as u32;
        for step in 0..steps {
            w.step();
            for (i, a) in w.animals().iter().enumerate().filter(|(_, a)| a.alive) {
                let p = a.body.position_m();
                assert!(p.is_finite(), "{body:?} animal {i} NaN at {step}");
                assert!(
                    tank.contains(p, 0.0),
                    "{body:?} animal {i} at {p} outside at {step}"
                );
                for v in [a.mental.hunger, a.mental.libido, a.mental.fear] {
                    assert!((0.0..=1.0).contains(&v));
                }
            }
            for f in w.food() {
                assert!(tank.contains(f.position_m, 0.0));
            }
        }
        let c = w.counts();
        assert_eq!(c.inside_rock_steps, 0, "{body:?}");
        if body == ReefBodyKind::PointMass {
            collisions += c.fish_collisions as f32;
            animal_minutes += w.animals().len() as f32 * secs / 60.0;
        } else {
            body_collisions += c.fish_collisions as f32;
            body_minutes += w.animals().len() as f32 * secs / 60.0;
        }
        eprintln!("{body:?} seed {seed}: {c:?}, events {}", w.events().len());
    }
    // Collisions stay rare: fewer than one start per animal per minute.
    assert!(
        collisions / animal_minutes < 1.0,
        "{collisions} collisions in {animal_minutes} animal-minutes"
    );
    assert!(
        body_collisions / body_minutes < 1.0,
        "muscle bodies: {body_collisions} collisions in {body_minutes} animal-minutes"
    );
}

#[test]
fn hungry_fish_find_and_eat_plankton() {
    for (body, at_least) in [(ReefBodyKind::PointMass, 12), (ReefBodyKind::Physical, 2)] {
        let mut w = reef(ReefScene::Feeding, body, 3);
        let start: Vec<f32> = w.animals().iter().map(|a| a.mental.hunger).collect();
        assert!(start.iter().all(|h| *h == 1.0), "{start:?}");
        run(&mut w, 60.0);
        let c = w.counts();
        eprintln!("{body:?} {c:?}");
        assert!(c.food_eaten >= at_least, "{body:?} {c:?}");
        // Every meal lowered the eater's hunger (the log says by how much).
        for e in w.events() {
            if let ReefEventKind::AteFood { .. } = e.kind {
                let (before, after) = e
                    .text
                    .split_once("hunger ")
                    .and_then(|(_, h)| h.trim_end_matches(')').split_once(" → "))
                    .unwrap();
                assert!(
                    after.parse::<f32>().unwrap() < before.parse::<f32>().unwrap(),
                    "{}",
                    e.text
                );
            }
        }
        let drops = w
            .events()
            .iter()
            .filter(|e| matches!(e.kind, ReefEventKind::AteFood { .. }))
            .count();
        assert_eq!(drops as u32, c.food_eaten.min(EVENT_LOG_LEN as u32));
    }
}

/// Plankton eaten by the six hungry fish of the *Feeding* demo in `secs`.
fn feeding_rate(body: ReefBodyKind, seed: u64, secs: f32) -> u32 {
    let mut w = reef(ReefScene::Feeding, body, seed);
    run(&mut w, secs);
    w.counts().food_eaten
}

/// Seconds until the first pair of the *Courtship* demo spawns (`None`
/// if not within `secs`), and the last phase any pair reached.
fn spawning_secs(body: ReefBodyKind, seed: u64, secs: f32) -> (Option<f32>, Option<Phase>) {
    spawning_secs_in(reef(ReefScene::Courtship, body, seed), secs)
}

/// [`spawning_secs`] in a given reef.
fn spawning_secs_in(mut w: ReefWorld, secs: f32) -> (Option<f32>, Option<Phase>) {
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

#[test]
#[ignore]
fn feeding_census() {
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

#[test]
fn muscle_fish_eat_at_least_55_percent_as_fast_as_point_mass_fish() {
    // Same seeds, same 60 s: the muscle body hovers at its food (swim-MC
    // off, fins braking) while the vacuum sucks it in, ranks the food it
    // sees counting half its detour round its turning circle, and climbs to
    // it at up to 44° (the fins set to the wished climb, trimming the body).
    // Slower than the point mass: it turns at about 24°/s in a circle of 1.2
    // body lengths, while the point mass turns and climbs on the spot (seeds
    // 1–8: muscle 202, point mass 342, 59 %; 132 s: 469 against 723, 65 %;
    // `feeding_census`, docs/departures.md).
    let (mut muscle, mut point) = (0, 0);
    for seed in 1..=8 {
        muscle += feeding_rate(ReefBodyKind::Physical, seed, 60.0);
        point += feeding_rate(ReefBodyKind::PointMass, seed, 60.0);
    }
    assert!(
        muscle as f32 >= 0.55 * point as f32,
        "muscle {muscle}, point mass {point}"
    );
}

/// Plankton eaten in `secs` of the *Feeding* demo with the default (muscle)
/// body, summed over `seeds`, each world changed by `tweak` first.
fn default_feeding_eaten(seeds: &[u64], secs: f32, tweak: impl Fn(&mut ReefWorld)) -> u32 {
    let mut total = 0;
    for &seed in seeds {
        let config = ReefConfig {
            seed,
            scene: ReefScene::Feeding,
            ..ReefConfig::default()
        };
        assert_eq!(config.body, ReefBodyKind::Physical, "the default body");
        let mut w = ReefWorld::new(config);
        tweak(&mut w);
        run(&mut w, secs);
        total += w.counts().food_eaten;
    }
    total
}

#[test]
fn muscle_fish_that_climb_steeply_eat_more_when_a_climb_costs_them_less() {
    // Two runs of the *Feeding* demo on the default (muscle) body that differ
    // only in how many metres of level swimming a metre of climbing counts
    // as when a fish ranks the food it sees
    // (`ReefParams::climb_effort_muscle_body`, 1.5 and the old 4). Climbing
    // at up to 44°, a fish that shuns food above or below it passes food it
    // could reach sooner. Seeds 2, 3, 7, 8, 60 s: 108 against 83 plankton;
    // seeds 1–8: 202 against 170 (60 s), 469 against 407 (132 s;
    // `feeding_agility_census`).
    let eaten = |effort: f32| {
        default_feeding_eaten(&[2, 3, 7, 8], 60.0, |w| {
            w.params_mut().climb_effort_muscle_body = effort
        })
    };
    assert_eq!(
        crate::sim::reef::params::ReefParams::default().climb_effort_muscle_body,
        1.5
    );
    let (light, heavy) = (eaten(1.5), eaten(4.0));
    assert!(
        light as f32 >= 1.15 * heavy as f32,
        "effort 1.5: {light}, effort 4: {heavy}"
    );
}

#[test]
fn muscle_fish_eat_more_when_they_rank_food_by_the_path_round_their_turning_circle() {
    // Two runs of the *Feeding* demo on the default (muscle) body that differ
    // only in how a fish ranks the food it sees: by the straight distance, or
    // counting half its detour round its turning circle
    // (`ReefParams::turning_path_weight`, 0 and 0.5). A fish that ranks by
    // distance often picks food beside or behind it and spends a third of its
    // chases turning round to it (`feeding_time_budget`). Seeds 3 and 7, 60 s:
    // 52 plankton against 40; seeds 1–8: 202 against 133 (60 s), 469 against
    // 284 (132 s, more on every seed; `feeding_agility_census`).
    let eaten = |path: bool| {
        default_feeding_eaten(&[3, 7], 60.0, |w| {
            w.params_mut().turning_path_weight = if path { 0.5 } else { 0.0 }
        })
    };
    let (by_path, by_distance) = (eaten(true), eaten(false));
    assert!(
        by_path as f32 >= 1.2 * by_distance as f32,
        "by path {by_path}, by distance {by_distance}"
    );
}

#[test]
fn an_eating_muscle_fish_hovers_with_its_mouth_at_the_food() {
    // One hungry fish, one particle half a body length ahead of its mouth.
    let mut w = reef(ReefScene::Feeding, ReefBodyKind::Physical, 1);
    let c = w.tank().center_m();
    for k in 1..w.animals().len() {
        w.animal_mut(k).unwrap().alive = false;
    }
    w.clear_food();
    w.place(0, c, Vec3::X);
    // Let it swim first: it must stop, not start from rest.
    let far = c + Vec3::X * 3.0;
    w.add_food(far);
    let mut hovered = Vec::new();
    for _ in 0..(20.0 / w.dt_secs()) as u32 {
        w.step();
        let a = &w.animals()[0];
        if a.mouth_open {
            hovered.push(a.body.velocity_m_per_s().length());
        }
        if w.counts().food_eaten > 0 {
            break;
        }
    }
    assert_eq!(w.counts().food_eaten, 1, "eaten within 20 s");
    let top = w.animals()[0].body.top_speed_m_per_s();
    // While the mouth is open (the food within reach) it slows to a hover.
    let last = *hovered.last().expect("the mouth opened");
    assert!(last < 0.2 * top, "speed {last} m/s at the food, top {top}");
    let m = match &w.animals()[0].body {
        ReefBody::Physical(p) => *p.motor(),
        ReefBody::Point(_) => unreachable!(),
    };
    assert_eq!(m.speed_fraction, 0.0, "no tail beat while hovering");
}

#[test]
fn the_courtship_demo_spawns_within_five_minutes_on_muscle_bodies() {
    // The default body of the demo; seeds 2-4 of the eight in the docs (seed 1
    // is the one of the eight that does not, natively and in the browser alike).
    for seed in 2..=4 {
        let (secs, phase) = spawning_secs(ReefBodyKind::Physical, seed, 300.0);
        assert!(
            secs.is_some(),
            "seed {seed}: reached {phase:?} in 5 minutes"
        );
    }
}

#[test]
fn the_courtship_demo_spawns_because_its_fish_digest_slowly() {
    // Two runs on the default (muscle) body that differ only in p0: the
    // demo's slow digestion spawns within 5 minutes; the paper's nominal p0
    // on the one clock makes the pair break up to feed, and it does not.
    use crate::sim::reef::mind::mental_state::NOMINAL_DIGESTION_RATE;
    let config = ReefConfig {
        scene: ReefScene::Courtship,
        seed: 2,
        ..ReefConfig::default()
    };
    assert_eq!(config.body, ReefBodyKind::Physical, "the default body");
    let mut nominal = config.clone();
    nominal.traits.pacifist.digestion_rate_per_unit = Some(NOMINAL_DIGESTION_RATE);
    let (demo, _) = spawning_secs_in(ReefWorld::new(config), 300.0);
    let (with_nominal, phase) = spawning_secs_in(ReefWorld::new(nominal), 300.0);
    assert!(demo.is_some(), "the demo spawns");
    assert!(
        with_nominal.is_none(),
        "nominal p0 spawned at {with_nominal:?} ({phase:?})"
    );
}

#[test]
fn the_courtship_demo_keeps_its_fish_fed_and_the_minds_panel_can_undo_it() {
    // Libido stays above hunger for the demo's five minutes (with the
    // nominal p0 hunger overtook it after about 30 s and the pairs broke
    // up to feed: 1 of 8 seeds spawned on muscle bodies).
    use crate::sim::reef::mind::mental_state::{hunger, libido};
    let w = reef(ReefScene::Courtship, ReefBodyKind::PointMass, 1);
    for a in w.animals() {
        let c = a.habits.mental;
        for t in [10.0, 60.0, 180.0, 300.0] {
            let h = hunger(&c, 0.7 * c.appetite_food_units, t);
            assert!(libido(&c, h, t) > h, "at {t} s: hunger {h}");
        }
    }
    use crate::sim::reef::mind::mental_state::NOMINAL_DIGESTION_RATE;
    let mut config = ReefConfig {
        scene: ReefScene::Courtship,
        seed: 1,
        ..ReefConfig::default()
    };
    config.traits.pacifist.digestion_rate_per_unit = Some(NOMINAL_DIGESTION_RATE);
    let w = ReefWorld::new(config);
    for a in w.animals() {
        assert_eq!(
            a.habits.mental.digestion_rate_per_unit,
            NOMINAL_DIGESTION_RATE
        );
    }
}

#[test]
#[ignore]
fn feeding_and_courtship_figures() {
    // `cargo test --release --lib feeding_and_courtship_figures -- --ignored --nocapture`
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

#[test]
fn the_shark_eats_prey_over_time() {
    let mut eaten = 0;
    for seed in 1..=4 {
        let mut w = reef(ReefScene::PredatorAndSchool, ReefBodyKind::PointMass, seed);
        let prey = w
            .animals()
            .iter()
            .filter(|a| a.habits.kind == FishKind::Prey)
            .count();
        let shark = shark_of(&w);
        run(&mut w, 300.0);
        let c = w.counts();
        assert_eq!(w.alive_count(), prey + 1 - c.prey_eaten as usize);
        // Each meal is logged and filled the shark.
        let meals = w.events().iter().filter(|e| matches!(e.kind, ReefEventKind::AtePrey { predator, .. } if predator as usize == shark)).count();
        assert_eq!(meals as u32, c.prey_eaten);
        eaten += c.prey_eaten;
    }
    assert!(eaten >= 4, "{eaten} prey eaten in 4 × 5 minutes");
}

#[test]
fn prey_that_sees_the_shark_flees() {
    for body in [ReefBodyKind::PointMass, ReefBodyKind::Physical] {
        let mut w = reef(ReefScene::PredatorAndSchool, body, 6);
        let shark = shark_of(&w);
        let c = w.tank().center_m();
        w.place(0, c, Vec3::X);
        // A fed shark cruises by instead of chasing.
        let s = w.animal_mut(shark).unwrap();
        let constants = s.habits.mental;
        s.mental.eat(&constants, 10.0);
        w.place(shark, c - Vec3::Z * 1.6, Vec3::X);
        let d0 = w.animals()[0]
            .body
            .position_m()
            .distance(w.animals()[shark].body.position_m());
        run(&mut w, 0.5);
        assert!(
            w.animals()[0].mental.fear > 0.5,
            "{body:?} fear {}",
            w.animals()[0].mental.fear
        );
        assert_eq!(
            w.animals()[0].focus.intention,
            Intention::Escape,
            "{body:?}"
        );
        run(&mut w, 2.5);
        let a = &w.animals()[0];
        let d1 = a
            .body
            .position_m()
            .distance(w.animals()[shark].body.position_m());
        assert!(
            !a.alive || d1 > d0 || a.focus.intention == Intention::Escape,
            "{body:?}"
        );
        assert!(d1 > d0 - 0.3, "{body:?} {d0} → {d1}");
    }
}

#[test]
fn a_pacifist_pair_completes_the_courtship_sequence_in_order() {
    let mut w = reef(ReefScene::Courtship, ReefBodyKind::PointMass, 1);
    run(&mut w, 120.0);
    let phases: Vec<(u32, u32, Phase)> = w
        .events()
        .iter()
        .filter_map(|e| match e.kind {
            ReefEventKind::Courtship {
                male,
                female,
                phase,
            } => Some((male, female, phase)),
            _ => None,
        })
        .collect();
    let order = [
        Phase::Looping,
        Phase::Circling,
        Phase::Ascending,
        Phase::Nuzzling,
        Phase::Spawned,
    ];
    let complete = phases.windows(5).any(|w| {
        w.iter()
            .zip(order)
            .all(|(e, p)| e.2 == p && e.0 == w[0].0 && e.1 == w[0].1)
    });
    assert!(complete, "{phases:?}");
    assert!(w.counts().spawnings >= 1);
    // Spawning satisfied both: their libido restarted from 0.
    let female = w
        .animals()
        .iter()
        .position(|a| a.habits.sex == Sex::Female)
        .unwrap();
    assert!(w.events().iter().any(|e| matches!(e.kind, ReefEventKind::Courtship { female: f, phase: Phase::Spawned, .. } if f as usize == female)));
    // A female only ever leaves a male for a larger one.
    for e in w.events() {
        if let ReefEventKind::LeftForLarger { old, new, .. } = e.kind {
            let len = |k: u32| w.animals()[k as usize].body.body_length_m();
            assert!(len(new) > len(old), "{}", e.text);
        }
    }
}

#[test]
fn an_eat_intention_interrupted_by_avoiding_is_resumed() {
    let mut w = reef(ReefScene::Feeding, ReefBodyKind::PointMass, 2);
    // Per fish: the last eat focus before an avoidance.
    let mut interrupted: Vec<Option<Target>> = vec![None; w.animals().len()];
    let mut last: Vec<Focus> = w.animals().iter().map(|a| a.focus).collect();
    let (mut interruptions, mut resumed) = (0, 0);
    for _ in 0..(90.0 / w.dt_secs()) as u32 {
        w.step();
        for (i, a) in w.animals().iter().enumerate() {
            let (before, now) = (last[i], a.focus);
            if before.intention == Intention::Eat && now.intention == Intention::Avoid {
                interrupted[i] = before.target;
                interruptions += 1;
                assert_eq!(a.generator.memory.map(|m| m.target), Some(before.target));
            }
            if before.intention == Intention::Avoid
                && now.intention != Intention::Avoid
                && let Some(t) = interrupted[i].take()
                && now.intention == Intention::Eat
                && now.target == Some(t)
            {
                resumed += 1;
            }
            last[i] = now;
        }
    }
    assert!(
        interruptions >= 3 && resumed >= 2,
        "{interruptions} interruptions, {resumed} resumed"
    );
}

/// Prey eaten in the *Predator and school* demo over `secs`, summed over
/// seeds 1–8, with every prey fish schooling or every one a loner; and
/// the strikes the shark missed.
fn prey_eaten_on(body: ReefBodyKind, schools: bool, secs: f32) -> (u32, u32) {
    prey_eaten_seeds(body, schools, secs, 1..=8)
}

/// [`prey_eaten_on`] over `seeds`.
fn prey_eaten_seeds(
    body: ReefBodyKind,
    schools: bool,
    secs: f32,
    seeds: std::ops::RangeInclusive<u64>,
) -> (u32, u32) {
    prey_eaten_with(body, schools, secs, seeds, |_| {})
}

/// [`prey_eaten_seeds`], with `setup` changing each reef before it runs.
fn prey_eaten_with(
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
                w.animal_mut(i).unwrap().habits.schools = schools;
            }
        }
        run(&mut w, secs);
        eaten += w.counts().prey_eaten;
        missed += w.counts().missed_strikes;
    }
    (eaten, missed)
}

#[test]
#[ignore]
fn predator_figures() {
    // `cargo test --release --lib predator_figures -- --ignored --nocapture`
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

#[test]
#[ignore]
fn predator_points_census() {
    for k in 0..4u64 {
        let r = 1 + 8 * k..=8 + 8 * k;
        let s = prey_eaten_seeds(ReefBodyKind::PointMass, true, 120.0, r.clone());
        let l = prey_eaten_seeds(ReefBodyKind::PointMass, false, 120.0, r.clone());
        println!("seeds {r:?}: schooling {s:?}, lone {l:?}");
    }
}

#[test]
fn lone_prey_are_taken_more_often_than_schooling_prey() {
    // The same shark, the same start; only the prey's schooling habit
    // differs. Schools flee together and crowd the shark's strikes
    // (confusion effect); loners are alone when it strikes. Counted over
    // 24 seeds: eight seeds' counts vary by about a tenth (seeds 1–8, 9–16,
    // 17–24, 25–32: schooling 33 / 34 / 30 / 28, lone 39 / 40 / 40 / 39;
    // `predator_points_census`).
    let (schooled, missed_in_school) =
        prey_eaten_seeds(ReefBodyKind::PointMass, true, 120.0, 1..=24);
    let (lone, missed_alone) = prey_eaten_seeds(ReefBodyKind::PointMass, false, 120.0, 1..=24);
    assert!(schooled > 0, "the shark eats schooling prey too");
    assert!(
        lone as f32 > 1.2 * schooled as f32,
        "lone {lone} vs schooling {schooled} prey eaten in 24 × 2 minutes"
    );
    assert!(
        missed_in_school > 2 * missed_alone,
        "missed strikes: {missed_in_school} at schools, {missed_alone} at loners"
    );
}

/// Prey eaten and strikes missed in *Predator and school* on the default
/// (muscle) body over `secs` and `seeds`, every prey fish schooling or every
/// one a loner, with fleeing schoolmates in the school's gait or not
/// (`BehaviourParams::escape_in_school_gait`).
fn muscle_prey_eaten(schools: bool, in_school_gait: bool, secs: f32, seeds: &[u64]) -> (u32, u32) {
    let body = ReefConfig::default().body;
    assert_eq!(body, ReefBodyKind::Physical, "the default body");
    prey_eaten_with(body, schools, secs, seeds.iter().copied(), |w| {
        w.params_mut().behaviour.escape_in_school_gait = in_school_gait;
    })
}

#[test]
fn on_muscles_too_lone_prey_are_taken_more_often_than_schooling_prey() {
    // The lesson of *Predator and school* on the default muscle body: the
    // same shark and start, every prey fish schooling or every one a loner.
    // Seeds 13–16 × 2 min (kept short: CI runs the tests unoptimised):
    // schooling 10, lone 15 (with fleeing schoolmates in the swim gait, 13
    // against 15); seeds 1–16 × 2 min: 41 against 57; seeds 1–16 × 5 min: 79
    // against 136, loners taken more on 15 of the 16 seeds
    // (`predator_strike_census`).
    let seeds: Vec<u64> = (13..=16).collect();
    let (schooled, missed_in_school) = muscle_prey_eaten(true, true, 120.0, &seeds);
    let (lone, missed_alone) = muscle_prey_eaten(false, true, 120.0, &seeds);
    assert!(schooled > 0, "the muscle shark eats schooling prey too");
    assert!(
        lone as f32 >= 1.3 * schooled as f32,
        "lone {lone} vs schooling {schooled} prey eaten in 4 × 2 minutes"
    );
    assert!(
        missed_in_school > 2 * missed_alone,
        "missed strikes: {missed_in_school} at schools, {missed_alone} at loners"
    );
}

#[test]
fn a_fleeing_muscle_school_stays_crowded_in_the_schools_gait() {
    // The cause of the lesson above: two runs of every seed that differ only in
    // the gait of schooling prey fleeing with schoolmates in view
    // (`BehaviourParams::escape_in_school_gait`). In the swim gait each fish
    // turns away alone with ballistic turn-MC turns and the school scatters
    // where the shark strikes; in the school's gait (the bridge) it flees as
    // one. Seeds 13–16 × 2 min: 3.65 other prey around the target at a
    // strike against 1.22, 10 eaten against 13; seeds 1–16: 2.81 against 1.92,
    // escaping prey with 4.83 neighbours within the confusion radius against
    // 3.99, 41 eaten against 43 (`predator_strike_census`).
    let census = |in_school_gait: bool| {
        let mut c = StrikeCensus::default();
        for seed in 13..=16 {
            c += strike_census(ReefBodyKind::Physical, true, in_school_gait, 120.0, seed);
        }
        c
    };
    let (together, alone) = (census(true), census(false));
    let crowd = |c: &StrikeCensus| c.crowd_at_strikes as f32 / (c.eaten + c.missed).max(1) as f32;
    assert!(
        crowd(&together) >= 1.5 * crowd(&alone),
        "prey around the target at a strike: {} in the school's gait, {} in the swim gait",
        crowd(&together),
        crowd(&alone)
    );
    assert!(
        together.eaten < alone.eaten,
        "eaten: {} in the school's gait, {} in the swim gait",
        together.eaten,
        alone.eaten
    );
}

#[test]
fn a_strike_at_prey_in_a_crowd_can_miss_and_at_a_loner_never_does() {
    let mut crowd_misses = 0;
    for seed in 1..=6 {
        for crowd in [0usize, 6] {
            let mut w = reef(ReefScene::PredatorAndSchool, ReefBodyKind::PointMass, seed);
            let shark = shark_of(&w);
            let c = w.tank().center_m();
            w.place(shark, c, Vec3::X);
            let prey: Vec<usize> = (0..w.animals().len()).filter(|&i| i != shark).collect();
            {
                // Already hunting the target (so it is not in the way).
                let s = w.animal_mut(shark).unwrap();
                s.mental.food_eaten = 0.0;
                s.focus = Focus {
                    intention: Intention::Eat,
                    target: Some(Target::Animal(prey[0] as u32)),
                };
                s.generator.current = s.focus;
            }
            // The target just ahead of the mouth, `crowd` others within
            // 1.2 of its body lengths, the rest far away.
            let mouth = w.animals()[shark].body.head_m();
            w.place(prey[0], mouth + Vec3::X * 0.12, Vec3::X);
            for (k, &i) in prey[1..].iter().enumerate() {
                let at = if k < crowd {
                    let a = k as f32 * std::f32::consts::TAU / crowd as f32;
                    // Beside the shark's path (not in its collision box).
                    mouth + Vec3::new(0.3, 0.5 * fmath::cos(a), 0.5 * fmath::sin(a))
                } else {
                    Vec3::new(-5.0, 0.6 + 0.3 * k as f32, -3.0)
                };
                w.place(i, at, Vec3::X);
            }
            for _ in 0..10 {
                let c = w.counts();
                if c.prey_eaten + c.missed_strikes > 0 {
                    break;
                }
                w.step();
            }
            let c = w.counts();
            if crowd == 0 {
                assert_eq!(
                    (c.prey_eaten, c.missed_strikes),
                    (1, 0),
                    "seed {seed}: a loner"
                );
            } else {
                assert_eq!(c.prey_eaten + c.missed_strikes, 1, "seed {seed}");
                crowd_misses += c.missed_strikes;
                if c.missed_strikes == 1 {
                    let e = w.events().back().unwrap();
                    assert!(
                        matches!(e.kind, ReefEventKind::Missed { crowd: 6, .. }),
                        "{e:?}"
                    );
                    assert!(e.text.contains("confused"), "{}", e.text);
                }
            }
        }
    }
    // Six neighbours: success 1/(1 + 6) per strike.
    assert!(
        crowd_misses >= 3,
        "{crowd_misses} misses in 6 crowded strikes"
    );
}

#[test]
fn a_hungry_shark_reaches_prey_that_hides_at_the_glass() {
    for body in [ReefBodyKind::PointMass, ReefBodyKind::Physical] {
        let mut w = reef(ReefScene::PredatorAndSchool, body, 3);
        let shark = shark_of(&w);
        let prey: Vec<usize> = (0..w.animals().len()).filter(|&i| i != shark).collect();
        let (lo, hi) = (w.tank().min_m, w.tank().max_m);
        // One prey fish still at the far glass; the others gone.
        w.place(prey[0], Vec3::new(hi.x - 0.3, 2.0, 0.0), Vec3::Z);
        for &i in &prey[1..] {
            w.animal_mut(i).unwrap().alive = false;
        }
        w.animal_mut(prey[0]).unwrap().habits.schools = false;
        w.place(shark, Vec3::new(lo.x + 4.0, 2.0, 0.0), Vec3::X);
        w.animal_mut(shark).unwrap().mental.food_eaten = 0.0;
        run(&mut w, 90.0);
        assert_eq!(w.counts().prey_eaten, 1, "{body:?}");
    }
}

#[test]
fn a_teachers_traits_change_every_fish_of_the_kind_at_once() {
    use crate::sim::reef::mind::habits::{DEVOTED_BODY_LENGTHS, MindTraits};
    use crate::sim::reef::mind::mental_state::RAVENOUS_DIGESTION_RATE;
    let mut w = reef(ReefScene::Reef, ReefBodyKind::PointMass, 2);
    run(&mut w, 5.0);
    let before: Vec<Habits> = w.animals().iter().map(|a| a.habits).collect();
    let at = w.animals()[0].body.position_m();
    let traits = KindTraits {
        pacifist: MindTraits {
            digestion_rate_per_unit: Some(RAVENOUS_DIGESTION_RATE),
            persistence_body_lengths: Some(DEVOTED_BODY_LENGTHS),
            ..MindTraits::default()
        },
        ..KindTraits::default()
    };
    w.set_traits(traits);
    for (a, b) in w.animals().iter().zip(&before) {
        if a.habits.kind == FishKind::Pacifist {
            assert_eq!(a.habits.mental.digestion_rate_per_unit, 0.005);
            assert_eq!(a.habits.persistence_body_lengths, 20.0);
            assert_eq!(a.habits.light, b.light, "their own tastes stay");
        } else {
            assert_eq!(a.habits, *b, "other kinds unchanged");
        }
    }
    assert_eq!(w.animals()[0].body.position_m(), at, "the reef goes on");
    // Ravenous pacifists are hungry again sooner than nominal ones.
    let mut nominal = reef(ReefScene::Reef, ReefBodyKind::PointMass, 2);
    run(&mut nominal, 5.0);
    run(&mut w, 20.0);
    run(&mut nominal, 20.0);
    let hunger = |w: &ReefWorld| {
        w.animals()
            .iter()
            .filter(|a| a.habits.kind == FishKind::Pacifist)
            .map(|a| a.mental.hunger)
            .sum::<f32>()
    };
    assert!(
        hunger(&w) > hunger(&nominal) + 0.5,
        "{} vs {}",
        hunger(&w),
        hunger(&nominal)
    );
    // Back to the demo's own values.
    w.set_traits(KindTraits::default());
    for (a, b) in w.animals().iter().zip(&before) {
        assert_eq!(a.habits, *b);
    }
}

#[test]
fn the_shark_picks_lone_prey_over_schooling_prey_at_the_same_distance() {
    // C_k = d_k (1 + β1 S_k + β2 E_k / π): at equal distance and turn, the
    // schooling fish costs 1.5 times more.
    let mut w = reef(ReefScene::PredatorAndSchool, ReefBodyKind::PointMass, 1);
    let shark = shark_of(&w);
    let c = w.tank().center_m();
    w.place(shark, c, Vec3::X);
    {
        let s = w.animal_mut(shark).unwrap();
        s.mental.food_eaten = 0.0;
        // A fresh mind that takes the cheapest prey at once (no earlier
        // target to be devoted to).
        s.generator = IntentionGenerator::default();
        s.habits.persistence_body_lengths = 0.0;
    }
    let prey: Vec<usize> = (0..w.animals().len()).filter(|&i| i != shark).collect();
    // A school of five to the right, one loner to the left and a little
    // farther (2.6 m against 2.2 m: without β1 the shark would take the
    // nearer schooling fish), the rest far behind.
    for (k, &i) in prey.iter().enumerate() {
        let at = match k {
            0 => c + Vec3::new(2.3, 0.0, 1.2),
            1..=5 => c + Vec3::new(2.0, 0.0, -1.0) + Vec3::new(0.0, 0.0, -0.35 * (k - 1) as f32),
            _ => c + Vec3::new(-5.5, 0.0, 3.5 - 0.3 * k as f32),
        };
        w.place(i, at, Vec3::X);
        w.animal_mut(i).unwrap().habits.schools = k != 0;
    }
    for _ in 0..3 {
        w.step();
    }
    let focus = w.animals()[shark].focus;
    assert_eq!(focus.intention, Intention::Eat);
    assert_eq!(
        focus.target,
        Some(Target::Animal(prey[0] as u32)),
        "the loner"
    );
}

#[test]
fn a_fish_flees_from_where_it_last_saw_the_predator_not_from_where_it_is() {
    for body in [ReefBodyKind::PointMass, ReefBodyKind::Physical] {
        let mut w = reef(ReefScene::PredatorAndSchool, body, 3);
        let shark = shark_of(&w);
        let c = w.tank().center_m();
        // The fish swims along +x and last saw the shark 1 m to its left
        // (+z); the shark has since moved to 3 m behind it, into its blind
        // cone, where the fish cannot see it. Everyone else is far away.
        w.place(0, c, Vec3::X);
        w.place(shark, c - Vec3::X * 3.0, Vec3::X);
        for k in 1..w.animals().len() {
            if k != shark {
                w.place(k, c + Vec3::new(-5.5, 0.0, 3.5 - 0.3 * k as f32), -Vec3::X);
            }
        }
        let s = w.animal_mut(shark).unwrap();
        let constants = s.habits.mental;
        s.mental.eat(&constants, 10.0);
        let remembered = c + Vec3::Z;
        let fish = w.animal_mut(0).unwrap();
        fish.habits.schools = false;
        fish.last_threat = Some((
            shark as u32,
            remembered,
            0.5 * crate::sim::reef::params::ReefParams::default().threat_memory_secs,
        ));
        w.step();
        let a = &w.animals()[0];
        assert_eq!(a.focus.intention, Intention::Escape, "{body:?}");
        assert_eq!(a.focus.target, Some(Target::Animal(shark as u32)));
        let away = a.desired_m_per_s.normalize_or_zero();
        // Away from the remembered place (−z), not from the true one (+x).
        assert!(away.dot(-Vec3::Z) > 0.8, "{body:?} flees along {away}");
        assert!(away.dot(Vec3::X) < 0.5, "{body:?} flees along {away}");
    }
}

#[test]
fn the_shark_counts_prey_as_schooling_by_its_schoolmates_not_its_intention() {
    // S_k = 1 for prey swimming among schoolmates, whatever it intends: a
    // loner that intends to school is as cheap as its distance; three fish
    // swimming together, none intending to school, cost 1.5 times theirs.
    let mut w = reef(ReefScene::PredatorAndSchool, ReefBodyKind::PointMass, 1);
    let shark = shark_of(&w);
    let c = w.tank().center_m();
    w.place(shark, c, Vec3::X);
    {
        let s = w.animal_mut(shark).unwrap();
        s.mental.food_eaten = 0.0;
        s.generator = IntentionGenerator::default();
        s.habits.persistence_body_lengths = 0.0;
    }
    let prey: Vec<usize> = (0..w.animals().len()).filter(|&i| i != shark).collect();
    // All swim along +x, away from the shark, which is in their blind cone
    // (they feel no fear); the loner is nearer than the group.
    for (k, &i) in prey.iter().enumerate() {
        let at = match k {
            0 => c + Vec3::new(2.0, 0.0, 0.5),
            1..=3 => c + Vec3::new(2.5, 0.0, -0.6 - 0.4 * (k - 1) as f32),
            _ => c + Vec3::new(-5.5, 0.0, 3.5 - 0.3 * k as f32),
        };
        w.place(i, at, Vec3::X);
        let a = w.animal_mut(i).unwrap();
        let constants = a.habits.mental;
        a.mental.eat(&constants, 10.0);
        a.habits.schools = k == 0;
        // What each intended at the last step (the shark reads the prey
        // before they decide anew).
        a.focus.intention = if k == 0 {
            Intention::School
        } else {
            Intention::Wander
        };
    }
    w.step();
    assert_eq!(w.animals()[prey[0]].focus.intention, Intention::School);
    for &i in &prey[1..=3] {
        assert_ne!(w.animals()[i].focus.intention, Intention::School);
    }
    let focus = w.animals()[shark].focus;
    assert_eq!(focus.intention, Intention::Eat);
    assert_eq!(
        focus.target,
        Some(Target::Animal(prey[0] as u32)),
        "the loner, though it means to school"
    );
}

#[test]
fn a_fish_is_in_a_school_with_two_mates_near_it_swimming_its_way() {
    let fish = |x: f32, z: f32, heading: Vec3| Seen {
        position_m: Vec3::new(x, 2.0, z),
        head_m: Vec3::new(x, 2.0, z),
        heading,
        velocity_m_per_s: heading * 0.2,
        length_m: 0.5,
        alive: true,
        kind: FishKind::Prey,
        sex: Sex::Female,
        species: 0,
        schooling: false,
    };
    let group = [
        fish(0.0, 0.0, Vec3::X),
        fish(0.0, 0.6, Vec3::X),
        fish(0.3, -0.6, Vec3::X),
    ];
    assert!((0..3).all(|i| in_a_school(
        &crate::sim::reef::params::PerceptionParams::default(),
        &group,
        i
    )));
    // One mate only: a pair is no school.
    assert!(!in_a_school(
        &crate::sim::reef::params::PerceptionParams::default(),
        &group[..2],
        0
    ));
    // Mates too far (beyond 3 body lengths) or crossing at a right angle.
    let far = [group[0], fish(0.0, 1.6, Vec3::X), fish(0.0, -1.6, Vec3::X)];
    assert!(!in_a_school(
        &crate::sim::reef::params::PerceptionParams::default(),
        &far,
        0
    ));
    let crossing = [group[0], fish(0.0, 0.6, Vec3::Z), fish(0.3, -0.6, Vec3::X)];
    assert!(!in_a_school(
        &crate::sim::reef::params::PerceptionParams::default(),
        &crossing,
        0
    ));
    // Another species is no schoolmate.
    let mut other = group;
    other[2].species = 1;
    assert!(!in_a_school(
        &crate::sim::reef::params::PerceptionParams::default(),
        &other,
        0
    ));
}

/// Fig. 17: does the muscle-driven school of the *School meets obstacle*
/// demo meet the pillar as one school, split, and join again within
/// `secs`? (one school, split, rejoined)
fn pillar_outcome(seed: u64, secs: f32) -> (bool, bool, bool) {
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

/// The pillar school's course: `PILLAR_SEED=8 cargo test --release --lib
/// pillar_trace -- --ignored --nocapture` prints every 3 s its mean x, speed,
/// groups, polarization and how many fish have a folded tail fin.
#[test]
#[ignore]
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

#[test]
#[ignore]
fn pillar_seeds() {
    for seed in 1..=10 {
        println!(
            "pillar seed {seed}: 60 s {:?}, 120 s {:?}",
            pillar_outcome(seed, 60.0),
            pillar_outcome(seed, 120.0)
        );
    }
}

#[test]
fn a_school_splits_around_the_pillar_and_joins_again() {
    // Fig. 17: muscle-driven prey swim from the left past a pillar in the
    // middle of the tank. (Seed 1, the teacher's default; of seeds 1–10, 1, 4,
    // 6 and 7 split and join again within the minute, 5 and 8 too within
    // two, measured with the fin trim and the libm functions (the browser's
    // runs); before them 8 and 9 within the minute. Which seeds do is
    // chaotic; `pillar_seeds` lists them.)
    let (before, split, rejoined) = pillar_outcome(1, 60.0);
    assert!(
        before && split && rejoined,
        "one school {before}, split {split}, rejoined {rejoined}"
    );
}
/// Share of fish-time (sampled every 9 steps) and number of muscle fish with a
/// folded tail fin in `secs` of `scene`.
fn folded_fins(scene: ReefScene, seed: u64, secs: f32) -> (f32, usize, usize) {
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

#[test]
fn tail_fins_never_fold_in_the_reef_and_the_predator_demo() {
    // With the tips tied to ring 5 only, 9 of 18 fish of the reef and 7 of 15
    // of the predator demo (seed 1) folded their fins within 2 minutes, for
    // 34 % and 40 % of the fish-time (`fold_census`, before the brace).
    for scene in [ReefScene::Reef, ReefScene::PredatorAndSchool] {
        let (share, fish, of) = folded_fins(scene, 1, 60.0);
        assert_eq!(
            fish, 0,
            "{scene:?}: {fish} of {of} fish, {share} of the time"
        );
    }
}

/// `cargo test --release --lib fold_census -- --ignored --nocapture`: folded
/// fins in every demo, two seeds, two minutes.
#[test]
#[ignore]
fn fold_census() {
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
/// `cargo test --release --lib courtship_seeds -- --ignored --nocapture`:
/// when the courtship demo spawns on seeds 1–16, both bodies.
#[test]
#[ignore]
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

/// Where the *Feeding* fish's time goes, for issue 13: each fish-step of
/// seeds 1–8 × 132 s in one of: mouth open at the food; chasing food at a
/// level bearing under 30°, 30–90°, 90° or more; chasing food more than 25°
/// above or below; eating with no food in view; anything else (avoiding…).
/// Then the chases: how many ended in a meal, were switched for other food,
/// or lost the food to another fish or the sand, with their mean length and
/// the mean distance at which they started. `cargo test --release --lib
/// feeding_time_budget -- --ignored --nocapture`.
#[test]
#[ignore]
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
/// 1.5 s while fewer drift. `cargo test --release --lib
/// feeding_variants_census -- --ignored --nocapture`.
#[test]
#[ignore]
fn feeding_variants_census() {
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
struct StrikeCensus {
    eaten: u32,
    missed: u32,
    /// Other prey within the confusion radius of the target, summed over
    /// every strike (eaten or missed).
    crowd_at_strikes: u32,
    /// Victims that were escaping (not schooling) when caught.
    victims_escaping: u32,
    /// Prey-seconds with fear above 0.5, and their neighbours within the
    /// confusion radius summed over those seconds.
    afraid_secs: f32,
    afraid_neighbours: f32,
    /// Of the afraid prey-seconds, those spent escaping, and the escaping
    /// prey's neighbours within the confusion radius summed over them.
    afraid_escaping_secs: f32,
    escaping_neighbours: f32,
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
fn strike_census(
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
            w.animal_mut(i).unwrap().habits.schools = schools;
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
        (a.join().unwrap(), b)
    });
    let mut c = a;
    c += b;
    c
}

#[test]
#[ignore]
fn predator_strike_census() {
    // `PROBE=muscles|points SEEDS=1-8 SECS=300 GAIT=1|0 [PERSEED=1] cargo test
    // --release --lib predator_strike_census -- --ignored --nocapture`: prey
    // eaten, strikes missed, the other prey within the confusion radius of
    // the target at the shark's strikes, and the neighbours of afraid and of
    // escaping prey, with every prey fish schooling and every one a loner.
    // GAIT=0 puts fleeing schoolmates in the swim gait.
    let body = match std::env::var("PROBE").as_deref() {
        Ok("points") => ReefBodyKind::PointMass,
        _ => ReefBodyKind::Physical,
    };
    let seeds = std::env::var("SEEDS").unwrap_or_else(|_| "1-8".into());
    let (a, b) = seeds.split_once('-').unwrap();
    let seeds = a.parse::<u64>().unwrap()..=b.parse::<u64>().unwrap();
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

#[test]
#[ignore]
fn reef_collision_census() {
    // Fish collisions on muscles with fleeing schoolmates in the school's gait
    // or the swim gait (`BehaviourParams::escape_in_school_gait`), seeds 1–8 ×
    // 1 min: `GAIT=1|0 cargo test --release --lib reef_collision_census --
    // --ignored --nocapture`.
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
/// chasepitch=0.44,effort=4" cargo test --release --lib feeding_agility_census
/// -- --ignored --nocapture`.
#[test]
#[ignore]
fn feeding_agility_census() {
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

/// Applies `feeding_agility_census`'s `key=value` tweaks to `w`: `finpitch`
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
