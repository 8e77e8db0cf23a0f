use super::*;
use crate::settings::share_link;
use serde_json::json;

/// A teacher's setting: the schooling lab, alignment a mystery at 37, speed
/// locked, the seed hidden, and a question.
fn lesson() -> Settings {
    let mut settings = Settings::default();
    settings
        .apply_patch(&json!({
            "scene": "boids",
            "left": {"alignment": 37, "fish_count": 80},
            "studio": {
                "question": "How strongly do these fish copy their neighbours?\nGuess the number.",
                "rules": {
                    "left.alignment": {"mystery": true},
                    "speed": {"locked": true},
                    "seed": {"hidden": true}
                }
            }
        }))
        .unwrap();
    settings
}

fn student(mut settings: Settings) -> Settings {
    settings.studio.student_view = true;
    settings
}

#[test]
fn rules_read_back_and_a_mystery_is_locked_and_hides_the_preset() {
    let s = lesson().studio;
    assert_eq!(
        s.rule("left.alignment"),
        ControlRule {
            mystery: true,
            ..Default::default()
        }
    );
    let effective = s.effective("left.alignment");
    assert!(effective.mystery && effective.locked && !effective.hidden);
    assert!(s.effective("speed").locked && !s.effective("speed").mystery);
    assert!(s.effective("seed").hidden);
    assert!(
        s.effective("left.preset").mystery,
        "the preset's name would give the weights away"
    );
    assert!(
        s.effective("left.cohesion").is_none(),
        "other weights stay free"
    );
    assert!(
        s.effective("right.preset").is_none(),
        "the other tank is free"
    );
    // A mystery preset makes every weight of its tank a mystery.
    let mut s = Studio::default();
    s.set_rule(
        "right.preset",
        ControlRule {
            mystery: true,
            ..Default::default()
        },
    );
    assert!(s.effective("right.separation").mystery);
    assert!(s.effective("left.separation").is_none());
    // The teacher's page: no rule meets its user.
    assert!(lesson().studio.for_student("left.alignment").is_none());
    assert!(
        student(lesson())
            .studio
            .for_student("left.alignment")
            .mystery
    );
}

#[test]
fn the_student_view_keeps_ruled_values_whatever_the_panel_did() {
    let before = student(lesson());
    let mut after = before.clone();
    after.left.alignment = 90.0; // a slider dragged
    after.speed = 4.0; // locked
    after.seed = 99; // hidden
    after.left.cohesion = 12.0; // free
    after.paused = true; // free
    after.studio.rules.clear(); // the studio itself
    before.studio.enforce(&before, &mut after);
    assert_eq!(after.left.alignment, 37.0);
    assert_eq!(after.speed, before.speed);
    assert_eq!(after.seed, before.seed);
    assert_eq!(after.left.cohesion, 12.0, "a free control changes");
    assert!(after.paused);
    assert_eq!(after.studio, before.studio);
    // A preset would move the mystery weight: it is kept too.
    let mut preset = before.clone();
    preset
        .left
        .load_preset(crate::settings::tank::Preset::Group);
    before.studio.enforce(&before, &mut preset);
    assert_eq!(preset.left.alignment, 37.0);
    // A free weight moved from a preset's mix: the label follows it (it is
    // a mystery, not kept).
    let mut group = student(lesson());
    group
        .apply_patch(&json!({"left": {"preset": "group"}}))
        .unwrap();
    group.studio.set_rule(
        "left.alignment",
        ControlRule {
            mystery: true,
            ..Default::default()
        },
    );
    let mut moved = group.clone();
    moved
        .apply_patch(&json!({"left": {"cohesion": 5}}))
        .unwrap();
    assert_eq!(moved.left.preset, crate::settings::tank::Preset::Custom);
    assert_eq!(group.studio.check_unchanged(&group, &moved), Ok(()));
    // The teacher's own page changes freely.
    let teacher = lesson();
    let mut moved = teacher.clone();
    moved.left.alignment = 90.0;
    teacher.studio.enforce(&teacher, &mut moved);
    assert_eq!(moved.left.alignment, 90.0);
}

#[test]
fn set_in_the_student_view_refuses_ruled_values_and_the_studio() {
    let before = student(lesson());
    for (patch, key) in [
        (json!({"left": {"alignment": 50}}), "left.alignment"),
        (json!({"left": {"preset": "group"}}), "left.alignment"),
        (json!({"speed": 2}), "speed"),
        (json!({"seed": 5}), "seed"),
        (json!({"studio": {"student_view": false}}), "studio"),
    ] {
        let mut after = before.clone();
        after.apply_patch(&patch).unwrap();
        let err = before.studio.check_unchanged(&before, &after).unwrap_err();
        assert_eq!(err.key, key, "{patch}: {err}");
        assert!(err.reason.contains("student"), "{err}");
    }
    let mut free = before.clone();
    free.apply_patch(&json!({"left": {"cohesion": 5}, "paused": true}))
        .unwrap();
    assert_eq!(before.studio.check_unchanged(&before, &free), Ok(()));
    // The teacher's page refuses nothing.
    let teacher = lesson();
    let mut after = teacher.clone();
    after.apply_patch(&json!({"speed": 2})).unwrap();
    assert_eq!(teacher.studio.check_unchanged(&teacher, &after), Ok(()));
}

#[test]
fn mystery_values_are_masked_in_settings_and_state_for_students_only() {
    let teacher = lesson();
    let mut json = serde_json::to_value(&teacher).unwrap();
    teacher.studio.mask_settings_json(&mut json);
    assert_eq!(json["left"]["alignment"], 37.0, "the teacher sees it");

    let pupil = student(teacher);
    let mut json = serde_json::to_value(&pupil).unwrap();
    pupil.studio.mask_settings_json(&mut json);
    assert_eq!(json["left"]["alignment"], MYSTERY);
    assert_eq!(json["left"]["preset"], MYSTERY);
    assert_eq!(json["left"]["cohesion"], 0.0, "free values stay");
    assert_eq!(json["speed"], 1.0, "locked is not secret");
    assert!(
        !json.to_string().contains("37"),
        "the number appears nowhere: {json}"
    );

    // state(): the selected fish's attention gives no weight away.
    let mut lab = crate::lab::Lab::new(pupil.clone());
    let mut with_fish = pupil.clone();
    with_fish.left.selected = Some(3);
    lab.apply_settings(with_fish);
    lab.step(2);
    let mut state =
        serde_json::to_value(crate::automation::StateReport::new(&lab, "webgl2", 0.0)).unwrap();
    assert_eq!(state["metrics"]["attention"]["urges"][1]["weight"], 37.0);
    pupil.studio.mask_state_json(&mut state);
    let urges = &state["metrics"]["attention"]["urges"];
    assert_eq!(urges[1]["urge"], "alignment");
    assert_eq!(urges[1]["weight"], MYSTERY);
    assert_eq!(urges[1]["strength_m_per_s2"], MYSTERY);
    assert!(urges[2]["weight"].is_number(), "cohesion is not a mystery");
    assert_eq!(state["student_view"], true);
}

#[test]
fn the_csv_of_a_student_view_with_mysteries_withholds_the_settings_link() {
    let mut lab = crate::lab::Lab::new(student(lesson()));
    lab.step(20);
    let csv = crate::export::scene_csv(&lab).text;
    assert!(csv.contains("# settings link: withheld"), "{csv}");
    assert!(!csv.contains("#v1."), "no link that holds the value");
    let teacher = crate::export::scene_csv(&crate::lab::Lab::new(lesson())).text;
    assert!(teacher.contains("# settings link: #v1."));
}

#[test]
fn studio_rules_and_question_survive_the_share_link() {
    for settings in [lesson(), student(lesson())] {
        let back = share_link::decode(&share_link::encode(&settings))
            .unwrap()
            .unwrap();
        assert_eq!(back, settings);
        assert_eq!(back.left.alignment, 37.0, "the fish still use the value");
    }
}

#[test]
fn malformed_rules_are_refused_naming_the_field_and_change_nothing() {
    for (studio, key, says) in [
        (
            json!({"rules": {"left.alignmnt": {"locked": true}}}),
            "studio.rules.left.alignmnt",
            "no control",
        ),
        (
            json!({"rules": {"left": {"hidden": true}}}),
            "studio.rules.left",
            "no control",
        ),
        (
            json!({"rules": {"studio.question": {"hidden": true}}}),
            "studio.rules.studio.question",
            "no control",
        ),
        (
            json!({"rules": {"speed": {"hiden": true}}}),
            "studio.rules.speed",
            "unknown flag 'hiden'",
        ),
        (
            json!({"rules": {"speed": {"locked": "yes"}}}),
            "studio.rules.speed",
            "true or false",
        ),
        (
            json!({"rules": {"speed": true}}),
            "studio.rules.speed",
            "expected a rule",
        ),
        (
            json!({"rules": ["speed"]}),
            "studio.rules",
            "expected an object",
        ),
        (json!({"question": 3}), "studio.question", "expected text"),
        (
            json!({"question": "?".repeat(QUESTION_MAX_CHARS + 1)}),
            "studio.question",
            "at most",
        ),
        (
            json!({"student_view": "yes"}),
            "studio.student_view",
            "true or false",
        ),
        (json!({"teacher": "me"}), "studio.teacher", "unknown"),
        (json!("locked"), "studio", "expected an object"),
    ] {
        let mut settings = lesson();
        let err = settings
            .apply_patch(&json!({"speed": 2, "studio": studio}))
            .unwrap_err()
            .to_string();
        assert!(
            err.starts_with(&format!("setting '{key}'")),
            "{studio}: {err}"
        );
        assert!(err.contains(says), "{studio}: {err}");
        assert_eq!(settings, lesson(), "nothing changed: {studio}");
        // The same in a link: refused with the field named.
        let mut json = serde_json::to_value(lesson()).unwrap();
        json["studio"] = studio.clone();
        let packed = miniz_oxide::deflate::compress_to_vec(json.to_string().as_bytes(), 6);
        use base64::Engine as _;
        let link = format!(
            "v1.{}",
            base64::engine::general_purpose::URL_SAFE_NO_PAD.encode(packed)
        );
        let err = share_link::decode(&link).unwrap_err().to_string();
        assert!(err.contains(&format!("'{key}'")), "{err}");
    }
}

#[test]
fn rules_merge_by_control_and_null_removes_one() {
    let mut settings = lesson();
    settings
        .apply_patch(&json!({"studio": {"rules": {
            "left.cohesion": {"hidden": true, "locked": true},
            "speed": null,
            "seed": {}
        }}}))
        .unwrap();
    let s = &settings.studio;
    assert!(s.rule("left.alignment").mystery, "kept");
    assert!(s.rule("left.cohesion").hidden && s.rule("left.cohesion").locked);
    assert!(s.rule("speed").is_none(), "removed by null");
    assert!(!s.rules.contains_key("seed"), "an empty rule is no rule");
    // Every scene's controls can be ruled, nested ones too.
    for key in [
        "physics.current_m_per_s",
        "reef.traits.predator.fear_threshold",
        "learning.annealing_steps",
        "left.obstacles",
        "scene",
        "paused",
    ] {
        let mut settings = Settings::default();
        settings
            .apply_patch(&json!({"studio": {"rules": {key: {"locked": true}}}}))
            .unwrap_or_else(|e| panic!("{key}: {e}"));
        assert!(settings.studio.rule(key).locked);
    }
}

#[test]
fn a_mystery_count_is_masked_in_its_own_scene_only() {
    let lab_state = |settings: &Settings| {
        let lab = crate::lab::Lab::new(settings.clone());
        serde_json::to_value(crate::automation::StateReport::new(&lab, "webgl2", 0.0)).unwrap()
    };
    for (scene, key) in [
        ("boids", "left.fish_count"),
        ("aquarium", "left.fish_count"),
        ("physics", "physics.fish_count"),
        ("reef", "reef.prey_count"),
    ] {
        let mut teacher = Settings::default();
        teacher
            .apply_patch(&json!({"scene": scene, "studio": {"rules": {key: {"mystery": true}}}}))
            .unwrap();
        let pupil = student(teacher.clone());
        let scene = pupil.scene;
        assert!(pupil.studio.count_is_mystery_for_student(scene), "{key}");
        assert!(
            !teacher.studio.count_is_mystery_for_student(scene),
            "the teacher sees the count"
        );
        let mut state = lab_state(&pupil);
        assert!(state["fish_count"].is_number());
        pupil.studio.mask_state_json(&mut state);
        assert_eq!(state["fish_count"], MYSTERY, "{key}");
        let mut shown = lab_state(&teacher);
        teacher.studio.mask_state_json(&mut shown);
        assert!(shown["fish_count"].is_number());
    }
    // The learning lab's swimmer count hides nothing; a mystery weight is not
    // a count.
    let pupil = student(lesson());
    assert!(!pupil.studio.count_is_mystery_for_student(Scene::Boids));
    assert!(!pupil.studio.count_is_mystery_for_student(Scene::Learning));
}

/// A link's JSON as a curious student reads it: the text after `#v1.`,
/// base64 decoded, inflated, parsed.
fn as_a_student_reads_it(link: &str) -> serde_json::Value {
    use base64::Engine as _;
    let body = link.trim_start_matches('#').strip_prefix("v1.").unwrap();
    let packed = base64::engine::general_purpose::URL_SAFE_NO_PAD
        .decode(body)
        .unwrap();
    let json = miniz_oxide::inflate::decompress_to_vec(&packed).unwrap();
    serde_json::from_slice(&json).unwrap()
}

/// Every number in a JSON value, wherever it sits.
fn numbers_in(value: &serde_json::Value, out: &mut Vec<f64>) {
    match value {
        serde_json::Value::Number(n) => out.extend(n.as_f64()),
        serde_json::Value::Array(list) => list.iter().for_each(|v| numbers_in(v, out)),
        serde_json::Value::Object(map) => map.values().for_each(|v| numbers_in(v, out)),
        _ => {}
    }
}

/// A typical lesson: a few locks and two mysteries with values no other
/// setting has (63 and 29), in the schooling lab.
pub(crate) fn two_mysteries(student_view: bool) -> Settings {
    let mut settings = Settings::default();
    settings
        .apply_patch(&json!({
            "scene": "boids",
            "left": {"alignment": 63, "cohesion": 29, "fish_count": 80, "sharks": 1},
            "studio": {
                "student_view": student_view,
                "question": "Which urge keeps this school together?",
                "rules": {
                    "left.alignment": {"mystery": true},
                    "left.cohesion": {"mystery": true},
                    "speed": {"locked": true},
                    "left.fish_count": {"locked": true},
                    "left.stingrays": {"hidden": true}
                }
            }
        }))
        .unwrap();
    settings
}

#[test]
fn decoding_a_student_link_shows_no_mystery_number_and_the_link_round_trips() {
    let settings = two_mysteries(true);
    let link = share_link::encode(&settings);
    let json = as_a_student_reads_it(&link);
    let mut numbers = Vec::new();
    numbers_in(&json, &mut numbers);
    for mystery in [63.0, 29.0] {
        assert!(!numbers.contains(&mystery), "{mystery} readable in {json}");
        let text = json.to_string();
        assert!(
            !text.contains(&format!(":{mystery}"))
                && !text.contains(&format!(":{}", mystery as i32)),
            "{text}"
        );
    }
    assert!(json["left"].get("alignment").is_none(), "{json}");
    assert!(
        json["left"].get("preset").is_none(),
        "the preset would name the mix"
    );
    assert!(json["sealed"].is_string(), "{json}");
    // The same lesson without the mystery rules carries the numbers in the
    // clear: the rule is what hides them.
    let mut open = settings.clone();
    open.studio.rules.remove("left.alignment");
    open.studio.rules.remove("left.cohesion");
    let mut numbers = Vec::new();
    numbers_in(
        &as_a_student_reads_it(&share_link::encode(&open)),
        &mut numbers,
    );
    assert!(
        numbers.contains(&63.0) && numbers.contains(&29.0),
        "{numbers:?}"
    );
    // The student's page holds exactly the teacher's values.
    let back = share_link::decode(&link).unwrap().unwrap();
    assert_eq!(back, settings);
    assert_eq!(back.left.alignment, 63.0);
    assert_eq!(back.left.cohesion, 29.0);
}

#[test]
fn a_mystery_equal_to_the_default_is_sealed_too() {
    let mut settings = two_mysteries(true);
    let default = Settings::default();
    settings.left.alignment = default.left.alignment;
    settings.left.cohesion = default.left.cohesion;
    settings.left.preset = settings.left.matching_preset();
    let link = share_link::encode(&settings);
    let json = as_a_student_reads_it(&link);
    assert!(json["left"].get("alignment").is_none(), "{json}");
    assert!(json["sealed"].is_string(), "{json}");
    assert_eq!(share_link::decode(&link).unwrap().unwrap(), settings);
}

#[test]
fn the_same_number_scrambles_differently_for_another_question() {
    let one = two_mysteries(true);
    let mut two = one.clone();
    two.studio.question = "What do the fish copy?".to_owned();
    let sealed = |s: &Settings| as_a_student_reads_it(&share_link::encode(s))["sealed"].clone();
    assert_ne!(sealed(&one), sealed(&two));
}

#[test]
fn a_damaged_sealed_value_is_refused_with_the_reason_named() {
    let link = share_link::encode(&two_mysteries(true));
    let json = as_a_student_reads_it(&link);
    let repack = |json: &serde_json::Value| share_link::pack_json(&json.to_string());
    let sealed = json["sealed"].as_str().unwrap().to_owned();
    // One character of the scramble changed.
    let mut flipped = json.clone();
    let mut chars: Vec<char> = sealed.chars().collect();
    chars[10] = if chars[10] == 'A' { 'B' } else { 'A' };
    flipped["sealed"] = json!(chars.into_iter().collect::<String>());
    // The question edited: the key no longer fits.
    let mut asked = json.clone();
    asked["studio"]["question"] = json!("Something else?");
    // Not base64, cut short, not text.
    let mut junk = json.clone();
    junk["sealed"] = json!("***");
    let mut short = json.clone();
    short["sealed"] = json!("AAA");
    let mut number = json.clone();
    number["sealed"] = json!(63);
    for (damaged, reason) in [
        (&flipped, "unscramble"),
        (&asked, "unscramble"),
        (&junk, "base64"),
        (&short, "too short"),
        (&number, "base64"),
    ] {
        let err = share_link::decode(&repack(damaged)).unwrap_err();
        assert!(
            matches!(err, share_link::ShareLinkError::Sealed(_)),
            "{err:?}"
        );
        let text = err.to_string();
        assert!(text.contains("mystery values are damaged"), "{text}");
        assert!(text.contains(reason), "{text}");
    }
}

#[test]
fn old_links_with_every_setting_and_plain_mystery_numbers_still_open() {
    // A link as the first studio made it: every setting, the number in clear.
    let settings = two_mysteries(true);
    let old = share_link::pack_json(&serde_json::to_string(&settings).unwrap());
    assert_eq!(share_link::decode(&old).unwrap().unwrap(), settings);
    assert!(
        old.len() > share_link::encode(&settings).len() * 2,
        "the new link is shorter"
    );
}
