//! Courtship: the pacifists' sequence in order, and the Courtship demo's pairs
//! spawning.

use super::*;

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
