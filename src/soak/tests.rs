use super::*;

/// The short soak CI runs: every scene, `SHORT_MINUTES` simulated minutes
/// after a 5 s warm-up, a change every 10 s, the extremes first at 10 s (so
/// all seven come in the first 80 s). In a debug build the boid tank's
/// 20,000 fish would take minutes a simulated second, so the extremes' counts
/// stop at [`SHORT_COUNT_MAX`] and random counts at 300; `shoal-lab soak`
/// runs the full extremes (docs/reliability.md).
const SHORT_MINUTES: f64 = 2.5;
const SHORT_COUNT_MAX: u32 = 600;

fn short(scene: Scene) -> SoakConfig {
    SoakConfig {
        warm_up_secs: 5.0,
        first_extremes_secs: 10.0,
        random_count_max: 300,
        extreme_count_max: Some(SHORT_COUNT_MAX),
        ..SoakConfig::new(scene, SHORT_MINUTES, 7)
    }
}

#[test]
fn a_short_soak_of_every_scene_breaks_no_rule() {
    let mut refused = 0;
    for scene in Scene::ALL {
        let mut changes = Vec::new();
        let report = soak(&short(scene), &|| None, &mut |t, what, outcome| {
            changes.push(format!("{t:.0} s {what}: {outcome:?}"));
        });
        eprintln!("{}", report.line());
        assert!(
            report.is_sound(),
            "{}\n{}",
            report.line(),
            changes.join("\n")
        );
        // It ran what it says: the simulated time, and the changes.
        let expected = SHORT_MINUTES * 60.0 + 2.0 * 5.0;
        assert!(
            (report.sim_secs - expected).abs() < 1.0,
            "{scene:?}: {} s",
            report.sim_secs
        );
        let changes_made = report.changes_applied + report.changes_refused;
        assert_eq!(changes_made, (SHORT_MINUTES * 6.0) as u64, "{scene:?}");
        assert!(
            report.changes_applied > changes_made / 3,
            "{}",
            report.line()
        );
        refused += report.changes_refused;
        // Every animal after every step (the learning lab has one swimmer).
        assert!(report.animal_checks >= report.steps, "{}", report.line());
        // The extremes came: the most animals the (lowered) counts allow.
        let seen = changes.iter().filter(|c| c.contains("extreme:")).count();
        assert_eq!(seen, 7, "{scene:?}:\n{}", changes.join("\n"));
    }
    assert!(refused > 0, "some changes are refused");
}

#[test]
fn the_extremes_apply_and_reach_the_counts_ends() {
    // The boid tank at its extremes: all seven apply, and the most animals
    // is the slider's 20,000 (only applied, not stepped: too slow in debug).
    let base = first_settings(Scene::Aquarium, 1);
    let mut lab = Lab::new(base.clone());
    for change in extremes(Scene::Aquarium, &base, None) {
        change
            .command
            .clone()
            .execute(&mut lab)
            .unwrap_or_else(|e| panic!("{}: {e}", change.what));
        let fish = lab.runs()[0].animal_count();
        match change.what.as_str() {
            "extreme: the most animals" => assert_eq!(fish, 20_000),
            "extreme: the fewest animals" => assert_eq!(fish, 0),
            "extreme: every number at its largest" => {
                let s = lab.settings();
                assert_eq!(s.left.fish_count, 20_000);
                assert_eq!(s.left.vision_distance_m, 12.0);
                assert_eq!(s.speed, crate::settings::SPEED_MAX);
            }
            "extreme: every weight 0" => assert_eq!(lab.settings().left.cohesion, 0.0),
            "extreme: every weight 100" => assert_eq!(lab.settings().right.alignment, 100.0),
            _ => {}
        }
    }
    assert_eq!(lab.settings(), &base, "back to the first settings");
    // Every scene's extremes apply.
    for scene in Scene::ALL {
        let base = first_settings(scene, 3);
        let mut lab = Lab::new(base.clone());
        for change in extremes(scene, &base, Some(50)) {
            let what = change.what.clone();
            if let Err(e) = change.command.execute(&mut lab) {
                panic!("{scene:?}: {what}: {e}");
            }
        }
    }
}

#[test]
fn the_soak_knows_how_to_change_every_setting() {
    let keys = setting_keys();
    assert!(keys.len() > 60, "{} keys", keys.len());
    let unknown: Vec<&String> = keys
        .iter()
        .filter(|(_, kind)| kind.is_none())
        .map(|(k, _)| k)
        .collect();
    assert!(unknown.is_empty(), "no way to change {unknown:?}");
    // Numbers come with their sliders, choices with every value.
    let kind = |key: &str| keys.iter().find(|(k, _)| k == key).unwrap().1.clone();
    assert!(matches!(kind("left.alignment"), Some(KeyKind::Slider(s)) if s.max == 100.0));
    assert!(matches!(
        kind("reef.traits.prey.fear_threshold"),
        Some(KeyKind::Slider(_))
    ));
    assert!(matches!(kind("reef.demo"), Some(KeyKind::Choice(v)) if v.len() == 5));
    assert_eq!(kind("physics.show_body"), Some(KeyKind::Switch));
}

fn fish_at(index: usize, p: Vec3) -> AnimalState {
    AnimalState {
        index,
        position_m: p,
        velocity_m_per_s: Some(Vec3::X),
        nodes_m: None,
    }
}

#[test]
fn the_checker_catches_a_nan_an_escape_and_a_fish_in_a_rock() {
    let tank = Tank::default();
    let rock = Obstacle::Rock {
        center_m: Vec3::new(2.0, 0.0, 0.0),
        radius_m: 1.0,
    };
    let rocks = [rock];
    let good = [
        fish_at(0, Vec3::new(-2.0, 1.0, 0.0)),
        fish_at(1, Vec3::new(2.0, 1.2, 0.0)),
    ];
    let mut v = Violations::default();
    check_states(&tank, &rocks, &good, 0.0, &mut v);
    assert_eq!(v.total(), 0, "{v:?}");

    let mut nan = fish_at(2, Vec3::new(0.0, 1.0, 0.0));
    nan.velocity_m_per_s = Some(Vec3::new(f32::NAN, 0.0, 0.0));
    let out = fish_at(3, Vec3::new(0.0, 4.6, 0.0));
    let in_rock = fish_at(4, Vec3::new(2.0, 0.5, 0.0));
    let mut node_out = fish_at(5, Vec3::new(0.0, 1.0, 0.0));
    let mut nodes = [Vec3::new(0.0, 1.0, 0.0); crate::sim::body::NODE_COUNT];
    nodes[7] = Vec3::new(6.2, 1.0, 0.0);
    node_out.nodes_m = Some(nodes);
    check_states(&tank, &rocks, &[nan, out, in_rock, node_out], 1.0, &mut v);
    assert_eq!(
        (v.not_finite, v.outside_tank, v.inside_rock),
        (1, 2, 1),
        "{v:?}"
    );
    assert_eq!(v.examples.len(), 4);
    // And a report with any of them is not sound.
    let report = SoakReport {
        violations: v,
        ..SoakReport::default()
    };
    assert!(!report.is_sound());
    assert!(SoakReport::default().is_sound());
}

#[test]
fn a_refusal_must_give_its_reason_and_name_its_setting() {
    use crate::settings::range::SettingError;
    let err = |key: &str, reason: &str| {
        AutomationError::Settings(SettingsError::Invalid(SettingError {
            key: key.to_owned(),
            reason: reason.to_owned(),
        }))
    };
    assert!(named(&err("left.alignment", "101 is out of range")));
    assert!(!named(&AutomationError::BadArgument(String::new())));
    assert!(!named(&AutomationError::BadArgument(
        "turn(deg): expected { $min }".to_owned()
    )));
    // A real refusal from the real path names the setting.
    let mut lab = Lab::new(Settings::default());
    let refused = Command::Set(json!({"left": {"alignment": 100.1}}))
        .execute(&mut lab)
        .unwrap_err();
    assert!(named(&refused), "{refused}");
    assert_eq!(refusal_kind(&refused), "setting left.alignment");
}

#[test]
fn the_changes_follow_their_schedule_and_the_page_draws_the_same() {
    let config = SoakConfig::new(Scene::Boids, 60.0, 5);
    let base = first_settings(Scene::Boids, 5);
    let lab = Lab::new(base.clone());
    let what = |i| change_at(&config, &base, &lab, i).what;
    // The first block of extremes at 60 s (change 6), the next 15 minutes on.
    assert!(!what(5).starts_with("extreme:"), "{}", what(5));
    assert_eq!(what(6), "extreme: every weight 0");
    assert_eq!(what(12), "extreme: back to the first settings");
    assert!(!what(13).starts_with("extreme:"));
    assert_eq!(what(6 + 90), "extreme: every weight 0");
    // The same index draws the same change; another draws another.
    assert_eq!(what(20), what(20));
    let drawn: std::collections::HashSet<String> = (20..60).map(what).collect();
    assert!(drawn.len() > 30, "{drawn:?}");
    // The page's request gives the same change, as a call of window.shoal.
    let request: ChangeRequest =
        serde_json::from_value(json!({"scene": "boids", "seed": 5, "index": 20})).unwrap();
    let page = request.change(&lab);
    assert_eq!(page["what"], json!(what(20)));
    let (call, arg) = change_at(&config, &base, &lab, 20).call();
    assert_eq!((page["call"].as_str().unwrap(), &page["arg"]), (call, &arg));
    let request: ChangeRequest = serde_json::from_value(
        json!({"scene": "reef", "seed": 5, "index": 0, "first_extremes_secs": 0, "count_max": 20}),
    )
    .unwrap();
    assert_eq!(request.change(&lab)["what"], "extreme: every weight 0");
    assert!(serde_json::from_value::<ChangeRequest>(json!({"scene": "reef"})).is_err());
    // Every kind of change is drawn: settings, bad values, selections,
    // rocks and commands.
    let calls: std::collections::HashSet<&str> = (0..400)
        .map(|i| change_at(&config, &base, &lab, 1000 + i).call().0)
        .collect();
    for call in ["set", "reset", "skip", "train", "race", "turn"] {
        assert!(calls.contains(call), "{call} never drawn: {calls:?}");
    }
    let bad = (0..400)
        .filter(|&i| change_at(&config, &base, &lab, 1000 + i).must_refuse)
        .count();
    assert!((10..80).contains(&bad), "{bad} bad values in 400");
}

#[test]
fn the_page_check_reports_what_the_checker_finds() {
    let lab = Lab::new(first_settings(Scene::Physics, 2));
    let report = check_json(&lab);
    assert_eq!(report["animals"], json!(lab.runs()[0].animal_count()));
    for key in [
        "not_finite",
        "outside_tank",
        "inside_rock",
        "metrics_not_finite",
    ] {
        assert_eq!(report[key], json!(0), "{key}: {report}");
    }
}
