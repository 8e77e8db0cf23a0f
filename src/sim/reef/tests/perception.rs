//! Perception: which prey the shark picks, what schooling means to it, and a
//! fish's memory of a predator it lost from view.

use super::*;

/// The point-mass *Predator and school* demo (seed 1) with its shark at the
/// tank's centre heading along +x, hungry, with a fresh mind that takes the
/// cheapest prey at once (no earlier target to be devoted to): the reef, the
/// shark, the centre and the prey.
fn hungry_shark_at_the_centre() -> (ReefWorld, usize, Vec3, Vec<usize>) {
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
    (w, shark, c, prey)
}

#[test]
fn the_shark_picks_lone_prey_over_schooling_prey_at_the_same_distance() {
    // C_k = d_k (1 + β1 S_k + β2 E_k / π): at equal distance and turn, the
    // schooling fish costs 1.5 times more.
    let (mut w, shark, c, prey) = hungry_shark_at_the_centre();
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
    let (mut w, shark, c, prey) = hungry_shark_at_the_centre();
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
