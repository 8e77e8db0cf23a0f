//! Minds: interrupted intentions resume, and a teacher's traits change every
//! fish of a kind.

use super::*;

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
