//! Every demo starts sound, runs for minutes in the tank and out of the rocks,
//! and a seed gives the same reef.

use super::*;

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
