//! Damaged links and `set()` patches as property tests (issue 35): a thousand
//! randomly damaged links of each kind (share, studio, experiment,
//! investigation) and a thousand random `set()` patches. Each one either
//! opens (applies) fully, to settings whose every value is in its range and
//! that reopen the same from their own link, or is refused with a sentence
//! naming the reason; none panics, and a refused patch changes nothing.
//!
//! The links and patches start from ones Shoal makes itself (several scenes,
//! a teacher's studio, the experiment files in `experiments/`, every
//! investigation), then are damaged as a copy, a chat program or a curious
//! student would: characters flipped, inserted, deleted, swapped or
//! repeated, the text cut short; inside the JSON, values replaced by numbers
//! out of range, huge or tiny, `"NaN"` and `"inf"` strings, the wrong type,
//! unknown keys, deep nesting. `docs/reliability.md` gives the counts and the
//! runtime.

use std::sync::LazyLock;

use proptest::prelude::*;
use proptest::sample::{Index, select};
use serde_json::{Map, Value, json};

use crate::automation::patched_settings;
use crate::experiment::design::{Design, MAX_RUNS};
use crate::experiment::link::{self as experiment_link, ExperimentLinkError};
use crate::investigation::catalogue::{INVESTIGATIONS, find};
use crate::investigation::link::{self as investigation_link, Request, split_patch};
use crate::investigation::setup_settings;
use crate::settings::share_link;
use crate::settings::{Scene, Settings, SettingsError};

/// Cases per property (issue 35: a thousand of each).
const CASES: u32 = 1_000;

fn config() -> ProptestConfig {
    ProptestConfig::with_cases(CASES)
}

// ---------------------------------------------------------------------------
// What Shoal makes: settings, studios, designs, investigation addresses.

fn patched(patch: Value) -> Settings {
    let mut settings = Settings::default();
    if let Err(err) = settings.apply_patch(&patch) {
        panic!("a base setting of the fuzz tests is refused: {err}: {patch}");
    }
    settings
}

/// Settings of every scene, with presets, modes, selections and obstacles.
static BASES: LazyLock<Vec<Settings>> = LazyLock::new(|| {
    let mut out: Vec<Settings> = Scene::ALL
        .iter()
        .map(|scene| patched(json!({ "scene": scene.name() })))
        .collect();
    out.push(patched(json!({
        "scene": "boids", "compare": true, "speed": 2.5, "seed": 4_294_967_295_u64,
        "show_vision": true,
        "left": {"preset": "group", "fish_count": 300, "selected": 5, "mode": "classic"},
        "right": {"alignment": 12.5, "sharks": 2, "fish_count": 40}
    })));
    out.push(patched(json!({
        "scene": "physics", "paused": true,
        "physics": {"fish_count": 3, "selected": 1, "hand_control": true, "current_m_per_s": 0.2}
    })));
    out.push(patched(json!({
        "scene": "reef", "reef": {"prey_count": 10, "food_count": 5, "follow": true}
    })));
    out.push(patched(json!({
        "scene": "learning", "learning": {"annealing_steps": 500, "training": true}
    })));
    let world = crate::sim::World::new(crate::sim::WorldConfig {
        seed: 3,
        fish_count: 0,
        ..Default::default()
    });
    let mut rocks = patched(json!({"scene": "aquarium", "left": {"fish_count": 60}}));
    rocks.left.obstacles = Some(world.obstacles().to_vec());
    rocks.right.obstacles = Some(Vec::new());
    out.push(rocks);
    out
});

/// A teacher's studios (rules, question), on a few of [`BASES`]; half of them
/// in the student view, as the *Share with class* link opens them.
static STUDIO_BASES: LazyLock<Vec<Settings>> = LazyLock::new(|| {
    let studios = [
        json!({
            "question": "How strongly do these fish copy their neighbours?\nGuess the number.",
            "rules": {
                "left.alignment": {"mystery": true},
                "speed": {"locked": true},
                "seed": {"hidden": true}
            }
        }),
        json!({
            "question": "Which urge holds the school together? Ça dépend… 🐟",
            "rules": {
                "right.preset": {"mystery": true},
                "left.fish_count": {"mystery": true, "hidden": true},
                "compare": {"locked": true}
            }
        }),
        json!({
            "rules": {
                "physics.fish_count": {"mystery": true},
                "reef.prey_count": {"locked": true},
                "learning.annealing_steps": {"hidden": true}
            }
        }),
    ];
    let mut out = Vec::new();
    for (i, studio) in studios.iter().enumerate() {
        for student_view in [false, true] {
            let mut settings = BASES[(i * 3 + 1) % BASES.len()].clone();
            if let Err(err) = settings.apply_patch(&json!({ "studio": studio })) {
                panic!("a studio of the fuzz tests is refused: {err}");
            }
            settings.studio.student_view = student_view;
            out.push(settings);
        }
    }
    out
});

/// The experiment files Shoal ships, and two designs with a range of levels,
/// a list of seeds, two factors and a share link as the base.
static DESIGNS: LazyLock<Vec<Design>> = LazyLock::new(|| {
    let files = [
        include_str!("../experiments/alignment-sweep.json"),
        include_str!("../experiments/physics-current.json"),
        include_str!("../experiments/school-size-shark.json"),
    ];
    let mut out: Vec<Design> = files
        .iter()
        .map(|text| Design::from_json(text).expect("a shipped experiment file"))
        .collect();
    let link = format!(
        "https://example.org/shoal/#{}",
        share_link::encode(&BASES[5])
    );
    out.push(
        serde_json::from_value(json!({
            "name": "two factors",
            "link": link,
            "settings": {"scene": "boids", "left": {"fish_count": 30}},
            "factors": [
                {"key": "left.cohesion", "levels": {"from": 0, "to": 100, "steps": 5}},
                {"key": "left.sharks", "levels": [0, 1]}
            ],
            "replicates": {"seeds": [3, 1, 4, 15, 9]},
            "warmup_secs": 2.5,
            "measure_secs": 10,
            "measures": [{"measure": "polarization", "summary": "series"}]
        }))
        .expect("a design"),
    );
    for design in &out {
        if let Err(err) = design.validate() {
            panic!("a base design of the fuzz tests is refused: {err}");
        }
    }
    out
});

/// Page addresses Shoal makes for investigations: the page, its language,
/// sometimes an experiment and a share link with them.
static INVESTIGATION_URLS: LazyLock<Vec<String>> = LazyLock::new(|| {
    let mut out = Vec::new();
    for (i, investigation) in INVESTIGATIONS.iter().enumerate() {
        let page = match i % 3 {
            0 => "https://example.org/shoal/".to_owned(),
            1 => "http://127.0.0.1:8080/?lang=fr".to_owned(),
            _ => experiment_link::link("https://example.org/shoal/?bench", &DESIGNS[0]),
        };
        let url = investigation_link::with_investigation(&page, investigation.id);
        out.push(url.clone());
        out.push(format!(
            "{url}#{}",
            share_link::encode(&BASES[i % BASES.len()])
        ));
    }
    out
});

/// Every setting's key path, to its values (objects and lists of obstacles
/// are values too; the studio is left out: its rules have their own keys).
fn leaf_paths(value: &Value, path: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
    match value {
        Value::Object(map) if !(path.len() == 1 && path[0] == "studio") => {
            for (key, inner) in map {
                path.push(key.clone());
                leaf_paths(inner, path, out);
                path.pop();
            }
        }
        _ if !path.is_empty() => out.push(path.clone()),
        _ => {}
    }
}

/// Each setting's key path and the values Shoal's own settings give it.
static LEAVES: LazyLock<Vec<(Vec<String>, Vec<Value>)>> = LazyLock::new(|| {
    let mut paths = Vec::new();
    let defaults = serde_json::to_value(Settings::default()).expect("settings serialise");
    leaf_paths(&defaults, &mut Vec::new(), &mut paths);
    paths.retain(|p| p[0] != "studio");
    let values: Vec<Value> = BASES
        .iter()
        .chain(STUDIO_BASES.iter())
        .map(|s| serde_json::to_value(s).expect("settings serialise"))
        .collect();
    paths
        .into_iter()
        .map(|path| {
            let mut seen: Vec<Value> = Vec::new();
            for v in &values {
                if let Some(x) = get(v, &path)
                    && !seen.contains(x)
                {
                    seen.push(x.clone());
                }
            }
            (path, seen)
        })
        .collect()
});

/// The dotted keys of every control a studio rule may name.
static CONTROL_KEYS: LazyLock<Vec<String>> =
    LazyLock::new(|| LEAVES.iter().map(|(path, _)| path.join(".")).collect());

// ---------------------------------------------------------------------------
// Damage.

/// One edit of a link's text, at positions taken modulo its length.
#[derive(Clone, Debug)]
enum Edit {
    Flip(Index, char),
    Insert(Index, char),
    Delete(Index),
    Truncate(Index),
    /// A piece of the text repeated (a paste done twice).
    Repeat(Index, Index),
    Swap(Index, Index),
}

fn any_char() -> impl Strategy<Value = char> {
    prop_oneof![
        4 => select(
            "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_"
                .chars()
                .collect::<Vec<_>>()
        ),
        2 => select(vec!['.', '#', '%', '=', '&', '?', '+', '/', ' ', '\n', 'v', '1', '2']),
        1 => any::<char>(),
    ]
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        3 => (any::<Index>(), any_char()).prop_map(|(i, c)| Edit::Flip(i, c)),
        2 => (any::<Index>(), any_char()).prop_map(|(i, c)| Edit::Insert(i, c)),
        2 => any::<Index>().prop_map(Edit::Delete),
        1 => any::<Index>().prop_map(Edit::Truncate),
        1 => (any::<Index>(), any::<Index>()).prop_map(|(i, j)| Edit::Repeat(i, j)),
        1 => (any::<Index>(), any::<Index>()).prop_map(|(i, j)| Edit::Swap(i, j)),
    ]
}

/// None (half the time: the damage is then in the JSON alone) or a few edits.
fn edits() -> impl Strategy<Value = Vec<Edit>> {
    prop_oneof![Just(Vec::new()), prop::collection::vec(edit(), 1..5),]
}

fn apply_edits(text: &str, edits: &[Edit]) -> String {
    let mut chars: Vec<char> = text.chars().collect();
    for edit in edits {
        let n = chars.len();
        if n == 0 {
            if let Edit::Insert(_, c) = edit {
                chars.push(*c);
            }
            continue;
        }
        match edit {
            Edit::Flip(i, c) => chars[i.index(n)] = *c,
            Edit::Insert(i, c) => chars.insert(i.index(n + 1), *c),
            Edit::Delete(i) => {
                chars.remove(i.index(n));
            }
            Edit::Truncate(i) => chars.truncate(i.index(n)),
            Edit::Repeat(i, j) => {
                let (a, b) = (i.index(n), j.index(n));
                let piece: Vec<char> = chars[a.min(b)..=a.max(b)].to_vec();
                chars.splice(a.max(b) + 1..a.max(b) + 1, piece);
            }
            Edit::Swap(i, j) => chars.swap(i.index(n), j.index(n)),
        }
    }
    chars.into_iter().collect()
}

/// Numbers a setting should refuse, or only just accept.
fn junk_number() -> impl Strategy<Value = Value> {
    prop_oneof![
        3 => select(vec![
            json!(0), json!(-1), json!(-0.0), json!(0.5), json!(1e-300), json!(-1e-300),
            json!(1e308), json!(-1e308), json!(f64::MAX), json!(f64::MIN_POSITIVE),
            json!(u64::MAX), json!(i64::MIN), json!(u32::MAX), json!(4_294_967_296_u64),
            json!(9_007_199_254_740_993_u64), json!(20_001), json!(100.000_01),
            json!(-100), json!(1e9), json!(360.5), json!(10_000), json!(10_001),
        ]),
        2 => (-200i64..30_000).prop_map(Value::from),
        2 => (-10.0f64..400.0).prop_map(Value::from),
        1 => any::<i64>().prop_map(Value::from),
        1 => any::<u64>().prop_map(Value::from),
        1 => any::<f64>().prop_map(|x| serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number)),
    ]
}

fn junk_text() -> impl Strategy<Value = Value> {
    prop_oneof![
        3 => select(vec![
            "NaN", "nan", "inf", "-inf", "Infinity", "-Infinity", "1e999", "", " ", "0x10",
            "12", "true", "null", "boids", "group", "custom", "classic", "mystery",
            "left.alignment", "why-school", "v1.", "\u{0}", "🐟", "<script>",
        ])
        .prop_map(|s| Value::String(s.to_owned())),
        1 => "\\PC{0,24}".prop_map(Value::String),
        1 => (1_001usize..1_200).prop_map(|n| Value::String("?".repeat(n))),
    ]
}

/// `depth` lists or objects, one inside the other, around a number.
fn nested(depth: usize, objects: bool) -> Value {
    let mut value = json!(1);
    for _ in 0..depth {
        value = if objects {
            json!({ "x": value })
        } else {
            json!([value])
        };
    }
    value
}

/// A value where a setting was: out of range, of the wrong type, nested.
fn junk() -> impl Strategy<Value = Value> {
    prop_oneof![
        5 => junk_number(),
        3 => junk_text(),
        1 => any::<bool>().prop_map(Value::Bool),
        1 => Just(Value::Null),
        1 => prop::collection::vec(junk_number(), 0..4).prop_map(Value::Array),
        1 => select(vec![json!({}), json!({"x": 1}), json!({"hidden": "yes"}), json!({"locked": true})]),
        1 => (1usize..300, any::<bool>()).prop_map(|(depth, objects)| nested(depth, objects)),
    ]
}

/// A key nobody wrote.
fn junk_key() -> impl Strategy<Value = String> {
    prop_oneof![
        select(vec![
            "wormhole",
            "",
            " ",
            "fishcount",
            "Speed",
            "left.alignment",
            "__proto__",
            "0",
            "constructor",
            "alignmnt",
            "studio",
            "investigation",
        ])
        .prop_map(str::to_owned),
        "\\PC{0,12}",
    ]
}

/// One piece of damage to a JSON document, at a node picked among its nodes
/// (or at a path Shoal knows, to reach deep into the settings).
#[derive(Clone, Debug)]
enum Damage {
    /// The value at a node replaced.
    Replace(Index, Value),
    /// A key removed from an object.
    Remove(Index),
    /// An unknown key added to an object.
    AddKey(Index, String, Value),
    /// The value at a node wrapped in `depth` lists or objects.
    Nest(Index, usize, bool),
    /// The value at a path (dotted, objects made on the way) set.
    SetAt(String, Value),
}

fn damage(paths: Vec<String>) -> impl Strategy<Value = Damage> {
    prop_oneof![
        3 => (any::<Index>(), junk()).prop_map(|(i, v)| Damage::Replace(i, v)),
        1 => any::<Index>().prop_map(Damage::Remove),
        1 => (any::<Index>(), junk_key(), junk()).prop_map(|(i, k, v)| Damage::AddKey(i, k, v)),
        1 => (any::<Index>(), 1usize..200, any::<bool>()).prop_map(|(i, d, o)| Damage::Nest(i, d, o)),
        4 => (select(paths), junk()).prop_map(|(p, v)| Damage::SetAt(p, v)),
    ]
}

fn damages(paths: Vec<String>) -> impl Strategy<Value = Vec<Damage>> {
    prop::collection::vec(damage(paths), 0..4)
}

/// Every node of `value` by its path (keys, and list places as numbers).
fn node_paths(value: &Value, path: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
    out.push(path.clone());
    match value {
        Value::Object(map) => {
            for (key, inner) in map {
                path.push(key.clone());
                node_paths(inner, path, out);
                path.pop();
            }
        }
        Value::Array(list) => {
            for (i, inner) in list.iter().enumerate() {
                path.push(i.to_string());
                node_paths(inner, path, out);
                path.pop();
            }
        }
        _ => {}
    }
}

fn get<'a>(root: &'a Value, path: &[String]) -> Option<&'a Value> {
    path.iter().try_fold(root, |v, key| match v {
        Value::Object(map) => map.get(key),
        Value::Array(list) => list.get(key.parse::<usize>().ok()?),
        _ => None,
    })
}

fn get_mut<'a>(root: &'a mut Value, path: &[String]) -> Option<&'a mut Value> {
    path.iter().try_fold(root, |v, key| match v {
        Value::Object(map) => map.get_mut(key),
        Value::Array(list) => list.get_mut(key.parse::<usize>().ok()?),
        _ => None,
    })
}

/// Sets the value at `path`, making objects (or growing lists) on the way.
fn set_at(root: &mut Value, path: &[&str], value: Value) {
    let Some((first, rest)) = path.split_first() else {
        *root = value;
        return;
    };
    if let Value::Array(list) = root {
        let at = first.parse::<usize>().unwrap_or(0);
        if at < list.len() {
            set_at(&mut list[at], rest, value);
        } else {
            let mut item = Value::Null;
            set_at(&mut item, rest, value);
            list.push(item);
        }
        return;
    }
    if !root.is_object() {
        *root = Value::Object(Map::new());
    }
    if let Value::Object(map) = root {
        set_at(
            map.entry((*first).to_owned()).or_insert(Value::Null),
            rest,
            value,
        );
    }
}

fn apply_damage(doc: &mut Value, damages: &[Damage]) {
    for damage in damages {
        let mut nodes = Vec::new();
        node_paths(doc, &mut Vec::new(), &mut nodes);
        match damage {
            Damage::Replace(i, value) => {
                if let Some(slot) = get_mut(doc, &nodes[i.index(nodes.len())]) {
                    *slot = value.clone();
                }
            }
            Damage::Remove(i) => {
                let path = &nodes[i.index(nodes.len())];
                if let Some((last, parent)) = path.split_last()
                    && let Some(Value::Object(map)) = get_mut(doc, parent)
                {
                    map.remove(last);
                }
            }
            Damage::AddKey(i, key, value) => {
                let objects: Vec<&Vec<String>> = nodes
                    .iter()
                    .filter(|p| get(doc, p).is_some_and(Value::is_object))
                    .collect();
                if !objects.is_empty() {
                    let path = objects[i.index(objects.len())].clone();
                    if let Some(Value::Object(map)) = get_mut(doc, &path) {
                        map.insert(key.clone(), value.clone());
                    }
                }
            }
            Damage::Nest(i, depth, objects) => {
                if let Some(slot) = get_mut(doc, &nodes[i.index(nodes.len())]) {
                    let mut value = slot.take();
                    for _ in 0..*depth {
                        value = if *objects {
                            json!({ "x": value })
                        } else {
                            json!([value])
                        };
                    }
                    *slot = value;
                }
            }
            Damage::SetAt(path, value) => {
                let path: Vec<&str> = path.split('.').collect();
                set_at(doc, &path, value.clone());
            }
        }
    }
}

/// A link's text (`v1.…`) with its JSON damaged, repacked, then its text
/// edited.
fn damaged_link(text: &str, damages: &[Damage], edits: &[Edit]) -> String {
    let text = if damages.is_empty() {
        text.to_owned()
    } else {
        let mut doc = share_link::unpack_json(text)
            .expect("Shoal's own link unpacks")
            .expect("and is not empty");
        apply_damage(&mut doc, damages);
        share_link::pack_json(&doc.to_string())
    };
    apply_edits(&text, edits)
}

// ---------------------------------------------------------------------------
// What every outcome must be.

/// With `SHOAL_FUZZ_STATS=1` in the environment, writes each case's outcome
/// (`share: refused: not-deflate`) on stderr, to count how often the cases
/// open and why they are refused: `cargo test --lib fuzz_tests --
/// --nocapture 2>&1 | grep '^fuzz ' | sort | uniq -c`.
fn note(outcome: &str) {
    if std::env::var_os("SHOAL_FUZZ_STATS").is_some() {
        eprintln!("fuzz {outcome}");
    }
}

fn settings_error_kind(err: &SettingsError) -> String {
    match err {
        SettingsError::NotAnObject(_) => "not an object".to_owned(),
        SettingsError::UnknownKey { .. } => "unknown key".to_owned(),
        SettingsError::Invalid(e) if e.key.starts_with("studio") => "studio".to_owned(),
        SettingsError::Invalid(e) => {
            let text = e.reason.as_str();
            if text.contains("out of range") {
                "out of range".to_owned()
            } else if text.contains("expected") || text.contains("invalid") {
                "wrong type".to_owned()
            } else {
                "other setting".to_owned()
            }
        }
    }
}

/// A refusal's sentence: there, and with every placeholder filled in.
fn assert_named(err: &dyn std::fmt::Display, case: &str) {
    let text = err.to_string();
    assert!(
        !text.trim().is_empty(),
        "a refusal without a reason: {case}"
    );
    // The catalogue writes a variable it was not given as `{$name}`; the
    // damaged text itself may hold anything.
    for (at, _) in text.match_indices("{$") {
        let name: String = text[at + 2..]
            .chars()
            .take_while(|c| c.is_ascii_lowercase() || *c == '-' || *c == '_')
            .collect();
        let placeholder = format!("{{${name}}}");
        assert!(
            name.is_empty() || !text[at..].starts_with(&placeholder) || case.contains(&placeholder),
            "a placeholder left in the reason: {text}"
        );
    }
}

/// A settings refusal names the setting it is about.
fn assert_settings_error(err: &SettingsError, case: &str) {
    assert_named(err, case);
    match err {
        SettingsError::Invalid(e) => {
            assert!(!e.key.is_empty(), "no key named: {err} ({case})");
            assert!(!e.reason.trim().is_empty(), "no reason: {err} ({case})");
        }
        SettingsError::UnknownKey { key, .. } => {
            assert!(err.to_string().contains(key.as_str()), "{err} ({case})");
        }
        SettingsError::NotAnObject(_) => {}
    }
}

/// Settings that opened: every value in range, and their own link reopens
/// them unchanged; a studio's rules give answers for every control.
fn assert_valid(settings: &Settings, case: &str) {
    if let Err(err) = settings.validate() {
        panic!("opened, but out of range: {err} ({case})");
    }
    let again = share_link::decode(&share_link::encode(settings));
    assert_eq!(
        again.as_ref().ok().and_then(Option::as_ref),
        Some(settings),
        "its own link does not reopen it ({case})"
    );
    let studio = &settings.studio;
    assert_eq!(studio.check_unchanged(settings, settings), Ok(()), "{case}");
    let mut student = settings.clone();
    studio.enforce(settings, &mut student);
    assert_eq!(&student, settings, "{case}");
    let mut json = serde_json::to_value(settings).expect("settings serialise");
    studio.mask_settings_json(&mut json);
    for key in CONTROL_KEYS.iter() {
        let _ = studio.for_student(key);
    }
}

fn link_error_kind(err: &share_link::ShareLinkError) -> &'static str {
    use share_link::ShareLinkError as E;
    match err {
        E::TooLong(_) => "too long",
        E::UnknownVersion => "unknown version",
        E::NotBase64 => "not base64",
        E::NotDeflate => "not deflate",
        E::NotJson => "not JSON",
        E::Sealed(_) => "sealed values damaged",
        E::Invalid(_) => "invalid",
    }
}

/// The page that opened a link builds its tanks and runs (a step of each).
fn assert_runs(settings: &Settings) {
    let mut lab = crate::lab::Lab::new(settings.clone());
    lab.step(1);
    assert_eq!(lab.settings().validate(), Ok(()));
}

fn check_share_link(kind: &str, text: &str) {
    match share_link::decode(text) {
        Ok(None) => {
            note(&format!("{kind}: no link"));
            assert!(
                text.trim().trim_start_matches('#').is_empty(),
                "a link taken for no link: {text}"
            );
        }
        Ok(Some(settings)) => {
            note(&format!("{kind}: opened"));
            assert_valid(&settings, text);
            assert_runs(&settings);
        }
        Err(share_link::ShareLinkError::Invalid(err)) => {
            note(&format!("{kind}: refused: {}", settings_error_kind(&err)));
            assert_settings_error(&err, text);
        }
        Err(err) => {
            note(&format!("{kind}: refused: {}", link_error_kind(&err)));
            assert_named(&err, text);
        }
    }
}

/// Dotted paths a share link's JSON damage aims at: every setting.
fn settings_paths() -> Vec<String> {
    CONTROL_KEYS.clone()
}

/// Paths into a studio: its fields, rules for real and unknown controls,
/// their flags.
fn studio_paths() -> Vec<String> {
    let mut paths: Vec<String> = [
        "studio",
        "studio.rules",
        "studio.question",
        "studio.student_view",
        "sealed",
    ]
    .iter()
    .map(|s| (*s).to_owned())
    .collect();
    for key in CONTROL_KEYS.iter().step_by(3) {
        paths.push(format!("studio.rules.{key}"));
        paths.push(format!("studio.rules.{key}.mystery"));
    }
    for key in [
        "left",
        "studio.question",
        "",
        "left.alignmnt",
        "a.b.c.d",
        "left.alignment.x",
    ] {
        paths.push(format!("studio.rules.{key}"));
    }
    paths
}

/// Paths into an experiment design.
fn design_paths() -> Vec<String> {
    let mut paths: Vec<String> = [
        "name",
        "description",
        "link",
        "settings",
        "factors",
        "factors.0",
        "factors.0.key",
        "factors.0.levels",
        "factors.0.levels.0",
        "factors.0.levels.from",
        "factors.0.levels.to",
        "factors.0.levels.steps",
        "factors.1",
        "factors.1.key",
        "factors.1.levels",
        "replicates",
        "replicates.count",
        "replicates.first_seed",
        "replicates.seeds",
        "replicates.seeds.0",
        "warmup_secs",
        "measure_secs",
        "measures",
        "measures.0",
        "measures.0.measure",
        "measures.0.summary",
        "measures.1.summary",
    ]
    .iter()
    .map(|s| (*s).to_owned())
    .collect();
    paths.extend(
        CONTROL_KEYS
            .iter()
            .step_by(2)
            .map(|k| format!("settings.{k}")),
    );
    paths
}

// ---------------------------------------------------------------------------
// `set()` patches.

/// One entry of a patch.
#[derive(Clone, Debug)]
enum Entry {
    /// A setting with a value Shoal's own settings give it.
    Plausible(Index, Index),
    /// A setting one of the studios' rules names, with a value Shoal's own
    /// settings give it (in the student view, refused unless unchanged).
    Ruled(Index, Index),
    /// A setting with a number that may be in range or not.
    Number(Index, Value),
    /// A setting with junk.
    Junk(Index, Value),
    /// A key nobody wrote, at the top or inside a group.
    Unknown(Index, String, Value),
    /// Part of a studio.
    Studio(String, Value),
    /// An investigation to open (or close, or junk).
    Investigation(Value),
}

fn entry() -> impl Strategy<Value = Entry> {
    let studio_value = prop_oneof![
        3 => select(vec![
            json!({"mystery": true}), json!({"locked": true}), json!({"hidden": true}),
            json!({}), json!(null), json!(true), json!(false), json!("why?"),
            json!({"locked": true, "hidden": false}),
        ]),
        1 => junk(),
    ];
    let investigation = prop_oneof![
        3 => select(INVESTIGATIONS.iter().map(|i| Value::from(i.id)).collect::<Vec<_>>()),
        1 => Just(Value::Null),
        1 => junk(),
    ];
    prop_oneof![
        6 => (any::<Index>(), any::<Index>()).prop_map(|(i, j)| Entry::Plausible(i, j)),
        2 => (any::<Index>(), any::<Index>()).prop_map(|(i, j)| Entry::Ruled(i, j)),
        4 => (any::<Index>(), prop_oneof![
            (0i64..200).prop_map(Value::from),
            (0.0f64..12.0).prop_map(Value::from),
            junk_number(),
        ]).prop_map(|(i, v)| Entry::Number(i, v)),
        2 => (any::<Index>(), junk()).prop_map(|(i, v)| Entry::Junk(i, v)),
        1 => (any::<Index>(), junk_key(), junk()).prop_map(|(i, k, v)| Entry::Unknown(i, k, v)),
        2 => (select(studio_paths()), studio_value).prop_map(|(p, v)| Entry::Studio(p, v)),
        1 => investigation.prop_map(Entry::Investigation),
    ]
}

/// The settings the studios of [`STUDIO_BASES`] keep from students.
const RULED: [&str; 9] = [
    "speed",
    "seed",
    "left.alignment",
    "right.preset",
    "left.fish_count",
    "compare",
    "physics.fish_count",
    "reef.prey_count",
    "learning.annealing_steps",
];

fn build_patch(entries: &[Entry]) -> Value {
    let mut patch = Value::Object(Map::new());
    for entry in entries {
        let (path, value): (Vec<String>, Value) = match entry {
            Entry::Plausible(i, j) => {
                let (path, seen) = &LEAVES[i.index(LEAVES.len())];
                let value = if seen.is_empty() {
                    Value::Null
                } else {
                    seen[j.index(seen.len())].clone()
                };
                (path.clone(), value)
            }
            Entry::Ruled(i, j) => {
                let key = RULED[i.index(RULED.len())];
                let (path, seen) = LEAVES
                    .iter()
                    .find(|(path, _)| path.join(".") == key)
                    .expect("a ruled key is a setting");
                (path.clone(), seen[j.index(seen.len())].clone())
            }
            Entry::Number(i, value) | Entry::Junk(i, value) => {
                (LEAVES[i.index(LEAVES.len())].0.clone(), value.clone())
            }
            Entry::Unknown(i, key, value) => {
                let (path, _) = &LEAVES[i.index(LEAVES.len())];
                let mut path = path[..path.len() - 1].to_vec();
                path.push(key.clone());
                (path, value.clone())
            }
            Entry::Studio(path, value) => {
                (path.split('.').map(str::to_owned).collect(), value.clone())
            }
            Entry::Investigation(value) => (vec!["investigation".to_owned()], value.clone()),
        };
        let path: Vec<&str> = path.iter().map(String::as_str).collect();
        set_at(&mut patch, &path, value);
    }
    patch
}

fn patch() -> impl Strategy<Value = Value> {
    prop_oneof![
        1 => junk(),
        12 => prop::collection::vec(entry(), 1..6).prop_map(|e| build_patch(&e)),
    ]
}

/// Numbers equal as the settings hold them (an `f32` slider holds 0.1 as
/// 0.1f32), everything else equal.
fn same(held: &Value, asked: &Value) -> bool {
    match (held, asked) {
        (Value::Number(a), Value::Number(b)) => match (a.as_u64(), b.as_u64()) {
            (Some(a), Some(b)) => a == b,
            _ => a.as_f64().map(|x| x as f32) == b.as_f64().map(|x| x as f32),
        },
        (Value::Array(a), Value::Array(b)) => {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| same(x, y))
        }
        (Value::Object(a), Value::Object(b)) => {
            a.len() == b.len() && a.iter().all(|(k, x)| b.get(k).is_some_and(|y| same(x, y)))
        }
        _ => held == asked,
    }
}

/// Every value the patch names is the one the settings hold (but a preset's
/// label, which tells the truth about the weights, and the studio, whose
/// rules merge).
fn assert_applied_fully(patch: &Value, after: &Settings, case: &str) {
    let held = serde_json::to_value(after).expect("settings serialise");
    let mut paths = Vec::new();
    leaf_paths(patch, &mut Vec::new(), &mut paths);
    for path in paths {
        if path[0] == "studio" || path.last().is_some_and(|k| k == "preset") {
            continue;
        }
        let Some(value) = get(&held, &path) else {
            panic!(
                "applied, but '{}' is not a setting ({case})",
                path.join(".")
            );
        };
        let asked = get(patch, &path).expect("the patch's own path");
        assert!(
            same(value, asked),
            "applied, but '{}' holds {value}, not {asked} ({case})",
            path.join(".")
        );
    }
}

/// `shoal.set(patch)` on `before`, as the app does it: the investigation part
/// split off, then the settings all or nothing.
fn check_set(before: &Settings, patch: &Value) {
    let case = patch.to_string();
    let (request, rest) = match split_patch(patch) {
        Ok(split) => split,
        Err(err) => {
            note("set: refused: investigation");
            return assert_named(&err, &case);
        }
    };
    let before = match request {
        Request::Open(investigation) => {
            &setup_settings(investigation).expect("an investigation's own settings")
        }
        Request::None | Request::Close => before,
    };
    let mut direct = before.clone();
    let applied = direct.apply_patch(&rest);
    match &applied {
        Ok(()) => {
            assert_valid(&direct, &case);
            assert_applied_fully(&rest, &direct, &case);
        }
        Err(err) => {
            assert_settings_error(err, &case);
            assert_eq!(&direct, before, "refused, but changed: {case}");
        }
    }
    match patched_settings(before, &rest) {
        Ok(after) => {
            note("set: applied");
            assert!(applied.is_ok(), "{case}");
            assert_eq!(after, direct, "{case}");
            // And the running lab takes it, as `shoal.set` gives it, and runs.
            let mut lab = crate::lab::Lab::new(before.clone());
            let set = crate::automation::Command::Set(rest.clone()).execute(&mut lab);
            assert_eq!(set, Ok(()), "{case}");
            assert_eq!(lab.settings(), &after, "the lab holds what was set: {case}");
            lab.step(1);
            assert_eq!(lab.settings().validate(), Ok(()), "{case}");
        }
        Err(err) => {
            note(&match &applied {
                Err(e) => format!("set: refused: {}", settings_error_kind(e)),
                Ok(()) => "set: refused: kept by the student view".to_owned(),
            });
            assert_named(&err, &case);
        }
    }
}

// ---------------------------------------------------------------------------
// The properties.

proptest! {
    #![proptest_config(config())]

    #[test]
    fn damaged_share_links_open_fully_or_are_refused_with_a_reason(
        base in any::<Index>(),
        damages in damages(settings_paths()),
        edits in edits(),
        hash in any::<bool>(),
    ) {
        let settings = &BASES[base.index(BASES.len())];
        let text = damaged_link(&share_link::encode(settings), &damages, &edits);
        check_share_link("share", &if hash { format!("#{text}") } else { text });
    }

    #[test]
    fn damaged_studio_links_open_fully_or_are_refused_with_a_reason(
        base in any::<Index>(),
        damages in damages(studio_paths()),
        edits in edits(),
    ) {
        let settings = &STUDIO_BASES[base.index(STUDIO_BASES.len())];
        let link = crate::ui::studio_panel::student_link(settings, "https://example.org/shoal/");
        let (page, fragment) = link.split_once('#').expect("a student link has a fragment");
        let fragment = damaged_link(fragment, &damages, &[]);
        let url = apply_edits(&format!("{page}#{fragment}"), &edits);
        // The page opens what follows its last `#`, as a pasted link is read.
        let fragment = url.rsplit_once('#').map_or(url.as_str(), |(_, f)| f);
        check_share_link("studio", fragment);
    }

    #[test]
    fn damaged_experiment_links_open_fully_or_are_refused_with_a_reason(
        base in any::<Index>(),
        damages in damages(design_paths()),
        edits in edits(),
    ) {
        let design = &DESIGNS[base.index(DESIGNS.len())];
        let text = damaged_link(&experiment_link::encode(design), &damages, &edits);
        match experiment_link::decode(&text) {
            Ok(plan) => {
                note("experiment: opened");
                assert_valid(&plan.base, &text);
                assert!(plan.run_count() <= MAX_RUNS, "{text}");
                assert!(!plan.seeds.is_empty() && !plan.measures.is_empty(), "{text}");
                for run in plan.runs().iter().step_by(97) {
                    assert_valid(&plan.settings_for(run), &text);
                }
                let again = experiment_link::decode(&experiment_link::encode(&plan.design));
                assert_eq!(again.as_ref(), Ok(&plan), "its own link does not reopen it");
            }
            Err(err) => {
                note(&match &err {
                    ExperimentLinkError::Damaged(e) => format!("experiment: refused: {}", link_error_kind(e)),
                    ExperimentLinkError::Empty => "experiment: refused: empty".to_owned(),
                    ExperimentLinkError::Refused(e) => format!(
                        "experiment: refused: design: {}",
                        e.field.split(['.', '[']).next().unwrap_or_default()
                    ),
                });
                assert_named(&err, &text);
            }
        }
    }

    #[test]
    fn damaged_investigation_links_open_fully_or_are_refused_with_a_reason(
        base in any::<Index>(),
        edits in prop::collection::vec(edit(), 1..5),
    ) {
        let url = apply_edits(&INVESTIGATION_URLS[base.index(INVESTIGATION_URLS.len())], &edits);
        match investigation_link::from_url(&url) {
            None => note("investigation: no investigation"),
            Some(Ok(investigation)) => {
                note("investigation: opened");
                assert_eq!(find(investigation.id), Some(investigation), "{url}");
                let settings = setup_settings(investigation).expect("its own settings");
                assert_valid(&settings, &url);
            }
            Some(Err(err)) => {
                note("investigation: refused");
                assert_named(&err, &url);
                let id = share_link::query_value(&url, investigation_link::KEY).unwrap_or_default();
                assert!(err.to_string().contains(id), "the id is named: {err}");
            }
        }
        // The page gives the app its address without the fragment
        // (`web/page.rs`), and the fragment apart: the investigation taken
        // out of the address leaves none, and the rest opens or is refused.
        let (page, fragment) = url.split_once('#').map_or((url.as_str(), None), |(p, f)| (p, Some(f)));
        assert_eq!(
            investigation_link::from_url(&investigation_link::without_investigation(page)),
            None,
            "{url}"
        );
        if let Some(Err(err)) = experiment_link::from_url(page) {
            assert_named(&err, &url);
        }
        if let Some(fragment) = fragment {
            check_share_link("investigation's fragment", fragment);
        }
    }

    #[test]
    fn random_set_patches_apply_fully_or_change_nothing(
        studio in any::<bool>(),
        base in any::<Index>(),
        patch in patch(),
    ) {
        // Half on a teacher's studio (half of those in the student view).
        let bases: &[Settings] = if studio { &STUDIO_BASES } else { &BASES };
        check_set(&bases[base.index(bases.len())], &patch);
    }
}

/// The bug these tests found: a damaged count of replicates was counted out
/// before it was refused (four billion seeds), and a first seed near 2^64
/// overflowed.
#[test]
fn a_huge_count_of_replicates_or_first_seed_is_refused_at_once() {
    for (replicates, field) in [
        (json!({"count": u32::MAX}), "replicates.count"),
        (json!({"count": 10_001}), "replicates.count"),
        (
            json!({"count": 3, "first_seed": u64::MAX}),
            "replicates.first_seed",
        ),
        (
            json!({"count": 3, "first_seed": u64::MAX - 1}),
            "replicates.first_seed",
        ),
    ] {
        let mut design = DESIGNS[0].clone();
        design.replicates = serde_json::from_value(replicates.clone()).expect("replicates");
        let err = experiment_link::decode(&experiment_link::encode(&design)).expect_err("refused");
        assert!(
            matches!(&err, ExperimentLinkError::Refused(e) if e.field == field),
            "{replicates}: {err}"
        );
    }
}
