//! The soak (issue 35): a scene run for a long simulated time while its
//! settings change every few simulated seconds, checking after every step
//! that no animal holds a NaN or infinity, leaves the tank or ends inside a
//! rock, and that every change is applied or refused with a named reason,
//! never with a panic.
//!
//! The changes go through the automation API as a script's `shoal.set(…)`,
//! `shoal.reset(…)`, `shoal.train(…)` do ([`Command::execute`], the same path
//! the page's `window.shoal` takes), and the simulation runs through
//! `shoal.step(n)` ([`crate::lab::Lab::step`]): the lab's steps, metrics and
//! traces, not the frame loop's wall-clock budget. After each change one
//! frame of the app's clock runs too ([`crate::lab::Lab::advance_frame`]), so
//! training and *Skip to the moment* take their per-frame share.
//!
//! What changes, every [`SoakConfig::change_every_secs`] of simulated time:
//! - a setting of the settings table, by the name `shoal.set` takes: a number
//!   anywhere on its slider (a fifth of the draws at each end), a switch
//!   flipped, a choice (preset, mode, demo, body, species…) picked; mostly
//!   settings that act in the scene, sometimes any setting at all;
//! - a value just outside its slider, or of the wrong kind, which must be
//!   refused naming the setting;
//! - a selected animal (one past the last, too), with following and steering
//!   by hand; the boid tanks' rocks (another seed's layout, none, the seed's);
//! - a command: a new seed, pause and play, *Skip to the moment*, training,
//!   the race, a turn.
//!
//! And, first at [`SoakConfig::first_extremes_secs`] and again every
//! [`SoakConfig::extremes_every_secs`], the extremes ([`extremes`]), each held
//! for one change's time: every weight 0, every weight 100, the most animals
//! the scene's counts allow (20,000 fish in a boid tank), none (the fewest),
//! every number at its slider's largest value at once (the largest values a
//! link can carry), every number at its least, and back to the start.
//!
//! Memory: the caller passes a probe of the heap in use (`shoal-lab soak`
//! counts allocations with a global allocator), read at the start, after a
//! warm-up at the first settings, and at the end after the same warm-up at the
//! same settings again, so that the last two compare like with like.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::panic::{AssertUnwindSafe, catch_unwind};

use glam::Vec3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde_json::{Map, Value, json};

use crate::automation::{AutomationError, Command};
use crate::lab::Lab;
use crate::settings::names::{Slider, setting_name};
use crate::settings::tank::{Preset, TankSettings};
use crate::settings::{Scene, Settings, SettingsError};
use crate::sim::boids::control_mode::ControlMode;
use crate::sim::common::obstacle::Obstacle;
use crate::sim::reef::demos::ReefScene;
use crate::sim::scene::AnimalState;
use crate::sim::{PhysicsBehaviour, Tank};

/// How far outside the glass (or inside a rock's surface) a point may be
/// before it counts as a violation, metres. Default 0.001 m (a millimetre):
/// rounding of `f32` positions a few metres from the origin, not a fish
/// slipping through.
pub const TOLERANCE_M: f32 = 0.001;

/// How far a muscle body's node may sink into a rock, metres. Default 0.02 m
/// (a tenth of a fish's width): the body's constraint pushes nodes out of
/// rocks between its spring substeps, so a node may touch a rock's skin
/// between them; the body's centre is held to [`TOLERANCE_M`].
pub const NODE_TOLERANCE_M: f32 = 0.02;

/// What a soak runs.
#[derive(Clone, Debug)]
pub struct SoakConfig {
    pub scene: Scene,
    /// Simulated seconds of changes (after the warm-up).
    pub sim_secs: f64,
    /// The seed of the changes (and of the world: the first settings' seed).
    pub seed: u64,
    /// Simulated seconds between two changes. Default 10 (issue 35).
    pub change_every_secs: f64,
    /// Simulated seconds at the first settings before the changes begin and
    /// again at the end, before each memory reading. Default 30.
    pub warm_up_secs: f64,
    /// When the first block of extremes begins, simulated seconds into the
    /// changes.
    pub first_extremes_secs: f64,
    /// Simulated seconds between two blocks of extremes.
    pub extremes_every_secs: f64,
    /// Most animals a random change of a count asks for (the extremes ask
    /// for the slider's most regardless): a boid tank's 20,000 fish held
    /// for minutes would make the hour take a day.
    pub random_count_max: u32,
    /// The scene's animal counts in the extremes at most this (`None`: the
    /// slider's most). Only the debug test's short soak lowers it.
    pub extreme_count_max: Option<u32>,
}

impl SoakConfig {
    /// The soak of issue 35 for `scene`: `minutes` of simulated time, a
    /// change every 10 s, the extremes first after a minute and every 15.
    pub fn new(scene: Scene, minutes: f64, seed: u64) -> Self {
        Self {
            scene,
            sim_secs: minutes * 60.0,
            seed,
            change_every_secs: 10.0,
            warm_up_secs: 30.0,
            first_extremes_secs: 60.0,
            extremes_every_secs: 900.0,
            random_count_max: 2_000,
            extreme_count_max: None,
        }
    }
}

/// What broke a rule, and how often.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Violations {
    /// Animal-states with a NaN or infinite position, velocity or node.
    pub not_finite: u64,
    /// Animal-states with the centre or a node outside the tank.
    pub outside_tank: u64,
    /// Animal-states with the centre or a node inside a rock.
    pub inside_rock: u64,
    /// School metrics (polarization, milling, distances, speed) that were
    /// NaN or infinite.
    pub metrics_not_finite: u64,
    /// The first few, in words.
    pub examples: Vec<String>,
}

impl Violations {
    pub fn total(&self) -> u64 {
        self.not_finite + self.outside_tank + self.inside_rock + self.metrics_not_finite
    }

    fn note(&mut self, example: impl FnOnce() -> String) {
        if self.examples.len() < 10 {
            self.examples.push(example());
        }
    }
}

/// Heap bytes in use, as the caller's probe reads them.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SoakMemory {
    /// After the lab was built at the first settings.
    pub start: Option<u64>,
    /// After the warm-up at the first settings.
    pub after_warm_up: Option<u64>,
    /// At the end, back at the first settings after the same warm-up.
    pub end: Option<u64>,
}

/// What a soak found.
#[derive(Clone, Debug, Default)]
pub struct SoakReport {
    pub scene: &'static str,
    pub seed: u64,
    /// Simulated seconds run, warm-ups included.
    pub sim_secs: f64,
    pub steps: u64,
    /// Animal-states checked (every living animal after every step).
    pub animal_checks: u64,
    /// Most animals in the tanks at once.
    pub most_animals: usize,
    pub changes_applied: u64,
    pub changes_refused: u64,
    /// Refusals by what refused them (`setting 'left.alignment'`, `step(n)`,
    /// `lab: …`).
    pub refusals: BTreeMap<String, u64>,
    /// Refusals whose message was empty, left a placeholder unfilled or did
    /// not name the setting: each is a failure.
    pub unnamed_refusals: Vec<String>,
    /// Changes out of a slider's range or of the wrong kind that were applied
    /// anyway: each is a failure.
    pub accepted_bad_values: Vec<String>,
    pub violations: Violations,
    /// The panic's message, if one happened (the soak stops there).
    pub panic: Option<String>,
    pub wall_secs: f64,
    pub memory: SoakMemory,
}

impl SoakReport {
    /// No violation, no panic, every refusal named, every bad value refused.
    pub fn is_sound(&self) -> bool {
        self.violations.total() == 0
            && self.panic.is_none()
            && self.unnamed_refusals.is_empty()
            && self.accepted_bad_values.is_empty()
    }

    /// One line of figures.
    pub fn line(&self) -> String {
        let mib = |b: Option<u64>| {
            b.map_or_else(
                || "-".to_owned(),
                |b| format!("{:.2}", b as f64 / 1048576.0),
            )
        };
        let mut line = format!(
            "{:<9} seed {} sim {:.0} s steps {} wall {:.1} s animal-checks {} most-animals {} \
             changes applied {} refused {} violations {} (nan {}, outside {}, rock {}, metrics {}) \
             unnamed-refusals {} accepted-bad {} panic {} heap MiB start {} warm {} end {}",
            self.scene,
            self.seed,
            self.sim_secs,
            self.steps,
            self.wall_secs,
            self.animal_checks,
            self.most_animals,
            self.changes_applied,
            self.changes_refused,
            self.violations.total(),
            self.violations.not_finite,
            self.violations.outside_tank,
            self.violations.inside_rock,
            self.violations.metrics_not_finite,
            self.unnamed_refusals.len(),
            self.accepted_bad_values.len(),
            self.panic.as_deref().unwrap_or("none"),
            mib(self.memory.start),
            mib(self.memory.after_warm_up),
            mib(self.memory.end),
        );
        for example in self
            .violations
            .examples
            .iter()
            .chain(&self.unnamed_refusals)
            .chain(&self.accepted_bad_values)
        {
            let _ = write!(line, "\n  {example}");
        }
        line
    }
}

/// One change: what it is, in words for the report, and the command.
#[derive(Clone, Debug)]
pub struct Change {
    pub what: String,
    pub command: Command,
    /// Must it be refused (a value out of range or of the wrong kind)?
    pub must_refuse: bool,
}

impl Change {
    /// The `window.shoal` method that makes this change and its argument
    /// (`null` for none).
    pub fn call(&self) -> (&'static str, Value) {
        match &self.command {
            Command::Set(patch) => ("set", patch.clone()),
            Command::Step(n) => ("step", json!(n)),
            Command::Pause => ("pause", Value::Null),
            Command::Play => ("play", Value::Null),
            Command::Reset(seed) => ("reset", json!(seed)),
            Command::Turn(deg) => ("turn", json!(deg)),
            Command::Train(n) => ("train", json!(n)),
            Command::Race => ("race", Value::Null),
            Command::LoadControllers(text) => ("load_controllers", json!(text)),
            Command::Skip => ("skip", Value::Null),
            Command::CancelSkip => ("cancel_skip", Value::Null),
        }
    }

    fn set(what: impl Into<String>, patch: Value) -> Self {
        Self {
            what: what.into(),
            command: Command::Set(patch),
            must_refuse: false,
        }
    }
}

/// What kind of setting a key of the settings is, for drawing a new value.
#[derive(Clone, Debug, PartialEq)]
pub enum KeyKind {
    Slider(Slider),
    Switch,
    Choice(Vec<Value>),
    /// An animal's index (`left.selected`, `reef.selected`).
    Selected,
    /// A boid tank's rocks.
    Obstacles,
    /// The scene: the soak stays in its own.
    Scene,
}

/// Every setting's dotted key and kind, from the settings as `shoal.set`
/// names them (the studio left out: its rules are not a simulation's).
/// `None` for a key the soak does not know how to change (a test checks
/// there is none).
pub fn setting_keys() -> Vec<(String, Option<KeyKind>)> {
    fn leaves(prefix: &str, value: &Value, out: &mut Vec<String>) {
        match value {
            Value::Object(map) if !map.is_empty() => {
                for (k, v) in map {
                    let key = if prefix.is_empty() {
                        k.clone()
                    } else {
                        format!("{prefix}.{k}")
                    };
                    if key != "studio" {
                        leaves(&key, v, out);
                    }
                }
            }
            _ => out.push(prefix.to_owned()),
        }
    }
    let defaults = serde_json::to_value(Settings::default()).unwrap_or_default();
    let mut keys = Vec::new();
    leaves("", &defaults, &mut keys);
    keys.into_iter()
        .map(|key| {
            let kind = key_kind(&key, value_at(&defaults, &key));
            (key, kind)
        })
        .collect()
}

fn value_at<'a>(root: &'a Value, key: &str) -> Option<&'a Value> {
    key.split('.').try_fold(root, |v, part| v.get(part))
}

fn choices<T: serde::Serialize>(all: &[T]) -> Option<KeyKind> {
    Some(KeyKind::Choice(
        all.iter()
            .filter_map(|v| serde_json::to_value(v).ok())
            .collect(),
    ))
}

fn key_kind(key: &str, default: Option<&Value>) -> Option<KeyKind> {
    let last = key.rsplit('.').next().unwrap_or(key);
    if let Some(slider) = setting_name(key).and_then(|n| n.slider) {
        return Some(KeyKind::Slider(slider));
    }
    match last {
        "scene" => return Some(KeyKind::Scene),
        "selected" => return Some(KeyKind::Selected),
        "obstacles" => return Some(KeyKind::Obstacles),
        "preset" => return choices(&Preset::ALL),
        "mode" => return choices(&ControlMode::ALL),
        "behaviour" => return choices(&PhysicsBehaviour::ALL),
        "demo" => return choices(&ReefScene::ALL),
        "overlay" => return choices(&crate::settings::reef::ReefOverlay::ALL),
        "body" => {
            use crate::sim::reef::world::ReefBodyKind;
            return choices(&[ReefBodyKind::Physical, ReefBodyKind::PointMass]);
        }
        "species" => {
            use crate::sim::BodySpecies;
            return choices(&[BodySpecies::Fish, BodySpecies::Shark]);
        }
        "controller" => {
            use crate::sim::learning::learning_lab::ControllerChoice;
            return choices(&[ControllerChoice::HandTuned, ControllerChoice::Learned]);
        }
        _ => {}
    }
    match default {
        Some(Value::Bool(_)) => Some(KeyKind::Switch),
        _ => None,
    }
}

/// `{"a": {"b": value}}` for the key `a.b`.
pub fn patch_for(key: &str, value: Value) -> Value {
    key.rsplit('.')
        .fold(value, |inner, part| json!({ part: inner }))
}

/// Merges `b` into `a` (objects key by key).
fn merge(a: &mut Value, b: Value) {
    match (a, b) {
        (Value::Object(a), Value::Object(b)) => {
            for (k, v) in b {
                merge(a.entry(k).or_insert(Value::Null), v);
            }
        }
        (a, b) => *a = b,
    }
}

/// Does a key change what happens in `scene` (its section's keys, the two
/// boid tanks' in the schooling lab, and the keys every scene has)?
fn acts_in(scene: Scene, key: &str) -> bool {
    let comparing = Settings {
        scene,
        compare: true,
        ..Settings::default()
    };
    let right_acts = scene.class().tanks(&comparing) == 2
        && key
            .strip_prefix("right.")
            .is_some_and(|rest| scene.class().acts(&format!("left.{rest}")));
    scene.class().acts(key)
        || right_acts
        || matches!(key, "speed" | "paused" | "seed" | "compare" | "show_vision")
}

/// A value anywhere on `slider`, a fifth of the draws at each end; a range
/// over orders of magnitude drawn evenly on a log scale; at most `cap`.
fn slider_value(rng: &mut ChaCha8Rng, slider: &Slider, cap: f64) -> Value {
    let max = slider.max.min(cap.max(slider.min));
    let r: f64 = rng.random();
    let x = if r < 0.2 {
        slider.min
    } else if r < 0.4 {
        max
    } else if slider.wide {
        let lo = slider.min.max(1.0);
        // libm: the page draws the same values (`sim::common::fmath`).
        let (a, b) = (libm::log(lo), libm::log(max.max(lo)));
        libm::exp(a + rng.random::<f64>() * (b - a))
    } else {
        slider.min + rng.random::<f64>() * (max - slider.min)
    };
    number(x.clamp(slider.min, slider.max), slider.whole)
}

fn number(x: f64, whole: bool) -> Value {
    if whole {
        json!(x.round() as u64)
    } else {
        // As a slider or a script gives it: an f32's digits.
        serde_json::Number::from_f64(f64::from(x as f32)).map_or(Value::Null, Value::Number)
    }
}

/// A value that must be refused: just outside the slider, or not a number.
fn bad_value(rng: &mut ChaCha8Rng, slider: &Slider) -> Value {
    let step = if slider.whole {
        1.0
    } else {
        (slider.max - slider.min).abs().max(1.0) * 1e-3
    };
    match rng.random_range(0..4) {
        0 => json!(slider.max + step),
        1 if slider.min - step >= 0.0 || !slider.whole => json!(slider.min - step),
        2 => json!("NaN"),
        _ => json!(1e308),
    }
}

/// The rocks of the boid world of `seed` (a layout Shoal makes itself).
fn rocks_of(seed: u64) -> Vec<Obstacle> {
    crate::sim::World::new(crate::sim::WorldConfig {
        seed,
        fish_count: 0,
        ..Default::default()
    })
    .obstacles()
    .to_vec()
}

/// Every number of the settings (every scene's section, the speed and the
/// seed: all a link carries) at its slider's least (`largest` false) or
/// most, in one patch; the scene's counts at most `count_max`.
fn all_numbers(scene: Scene, largest: bool, count_max: Option<u32>) -> Value {
    let count_keys = scene.class().facts().count_keys;
    let mut patch = json!({});
    for (key, kind) in setting_keys() {
        let Some(KeyKind::Slider(slider)) = kind else {
            continue;
        };
        let mut x = if largest { slider.max } else { slider.min };
        if count_keys.contains(&key.as_str())
            && let Some(cap) = count_max
        {
            x = x.min(f64::from(cap)).max(slider.min);
        }
        merge(&mut patch, patch_for(&key, number(x, slider.whole)));
    }
    patch
}

/// The extremes, in order, each held for one change's time.
pub fn extremes(scene: Scene, base: &Settings, count_max: Option<u32>) -> Vec<Change> {
    let weights = |w: f32| {
        let tank: Map<String, Value> = TankSettings::WEIGHTS
            .iter()
            .map(|s| (s.range.key.to_owned(), json!(w)))
            .collect();
        json!({"left": tank.clone(), "right": tank})
    };
    let counts = |most: bool| {
        let mut patch = json!({});
        for key in scene.class().facts().count_keys {
            if let Some(slider) = setting_name(key).and_then(|n| n.slider) {
                let x = if most {
                    count_max.map_or(slider.max, |c| slider.max.min(f64::from(c)))
                } else {
                    slider.min
                };
                merge(&mut patch, patch_for(key, number(x, true)));
            }
        }
        // A scene without counts (the learning lab): its longest and
        // shortest training instead.
        if patch.as_object().is_some_and(Map::is_empty) {
            let key = "learning.annealing_steps";
            if let Some(slider) = setting_name(key).and_then(|n| n.slider) {
                let x = if most { slider.max } else { slider.min };
                patch = patch_for(key, number(x, true));
            }
        }
        patch
    };
    let mut back = serde_json::to_value(base).unwrap_or_default();
    if let Some(map) = back.as_object_mut() {
        map.remove("studio");
    }
    vec![
        Change::set("extreme: every weight 0", weights(0.0)),
        Change::set("extreme: every weight 100", weights(100.0)),
        Change::set("extreme: the most animals", counts(true)),
        Change::set("extreme: the fewest animals", counts(false)),
        Change::set(
            "extreme: every number at its largest",
            all_numbers(scene, true, count_max),
        ),
        Change::set(
            "extreme: every number at its least",
            all_numbers(scene, false, count_max),
        ),
        Change::set("extreme: back to the first settings", back),
    ]
}

/// The change number `index` (from 0) of the soak `config`, for `lab` as it
/// is now: an extreme where a block of them falls, else a random one drawn
/// from the config's seed and the index (so the browser's soak, which asks
/// for them one at a time, draws the same).
pub fn change_at(config: &SoakConfig, base: &Settings, lab: &Lab, index: u64) -> Change {
    let per = |secs: f64| (secs / config.change_every_secs).round().max(0.0) as u64;
    let first = per(config.first_extremes_secs);
    let extremes_list = extremes(config.scene, base, config.extreme_count_max);
    let every = per(config.extremes_every_secs).max(extremes_list.len() as u64 + 1);
    if index >= first {
        let at = ((index - first) % every) as usize;
        if let Some(change) = extremes_list.get(at) {
            return change.clone();
        }
    }
    let mut rng =
        ChaCha8Rng::seed_from_u64(config.seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ index);
    random_change(&mut rng, lab, config)
}

/// One random change for `lab` (see the module doc).
pub fn random_change(rng: &mut ChaCha8Rng, lab: &Lab, config: &SoakConfig) -> Change {
    let scene = config.scene;
    let keys = setting_keys();
    let acting: Vec<&(String, Option<KeyKind>)> =
        keys.iter().filter(|(k, _)| acts_in(scene, k)).collect();
    let count_keys = scene.class().facts().count_keys;
    let roll = rng.random_range(0..100);
    let pick_key = |rng: &mut ChaCha8Rng, any: bool| {
        if any {
            keys[rng.random_range(0..keys.len())].clone()
        } else {
            acting[rng.random_range(0..acting.len())].clone()
        }
    };
    match roll {
        // A setting: mostly one acting in the scene.
        0..=69 => {
            let (key, kind) = pick_key(rng, roll >= 58);
            let value = match kind {
                Some(KeyKind::Slider(slider)) => {
                    let cap = if count_keys.contains(&key.as_str())
                        || key.ends_with("fish_count")
                        || key.ends_with("prey_count")
                    {
                        f64::from(config.random_count_max)
                    } else {
                        f64::INFINITY
                    };
                    slider_value(rng, &slider, cap)
                }
                Some(KeyKind::Switch) => {
                    let now = value_at(&lab_settings_value(lab), &key)
                        .and_then(Value::as_bool)
                        .unwrap_or(false);
                    json!(!now)
                }
                Some(KeyKind::Choice(values)) => values[rng.random_range(0..values.len())].clone(),
                Some(KeyKind::Selected) => selection(rng, lab),
                Some(KeyKind::Obstacles) => obstacles(rng),
                Some(KeyKind::Scene) | None => json!(scene.name()),
            };
            Change::set(format!("{key} = {value}"), patch_for(&key, value))
        }
        // A value that must be refused.
        70..=77 => {
            let sliders: Vec<(String, Slider)> = keys
                .iter()
                .filter_map(|(k, kind)| match kind {
                    Some(KeyKind::Slider(s)) => Some((k.clone(), *s)),
                    _ => None,
                })
                .collect();
            let (key, slider) = sliders[rng.random_range(0..sliders.len())].clone();
            let value = bad_value(rng, &slider);
            Change {
                what: format!("{key} = {value} (must be refused)"),
                command: Command::Set(patch_for(&key, value)),
                must_refuse: true,
            }
        }
        // Pick an animal, and follow or steer it.
        78..=84 => {
            let section = scene.class().facts().settings_section;
            let mut patch = patch_for(&format!("{section}.selected"), selection(rng, lab));
            if rng.random_bool(0.5) {
                let key = if rng.random_bool(0.5) {
                    "follow"
                } else {
                    "hand_control"
                };
                merge(
                    &mut patch,
                    patch_for(&format!("{section}.{key}"), json!(rng.random_bool(0.7))),
                );
            }
            Change::set(format!("select: {patch}"), patch)
        }
        // The boid tanks' rocks.
        85..=87 => {
            let side = if rng.random_bool(0.5) {
                "left"
            } else {
                "right"
            };
            let value = obstacles(rng);
            Change::set(
                format!(
                    "{side}.obstacles = {} rocks",
                    value.as_array().map_or(0, Vec::len)
                ),
                patch_for(&format!("{side}.obstacles"), value),
            )
        }
        // A command.
        _ => {
            let (what, command) = match rng.random_range(0..8) {
                0 => {
                    let seed = rng.random_range(0..1_000_000u64);
                    (format!("reset({seed})"), Command::Reset(Some(seed)))
                }
                1 => ("reset()".to_owned(), Command::Reset(None)),
                2 => {
                    let pause = !lab.settings().paused;
                    let name = if pause { "pause()" } else { "play()" };
                    (
                        name.to_owned(),
                        if pause { Command::Pause } else { Command::Play },
                    )
                }
                3 => ("skip()".to_owned(), Command::Skip),
                4 => ("cancel_skip()".to_owned(), Command::CancelSkip),
                5 => {
                    let n = rng.random_range(1..=20);
                    (format!("train({n})"), Command::Train(n))
                }
                6 => ("race()".to_owned(), Command::Race),
                _ => {
                    let deg = rng.random_range(-180.0f32..=180.0);
                    (format!("turn({deg:.0})"), Command::Turn(deg))
                }
            };
            Change {
                what,
                command,
                must_refuse: false,
            }
        }
    }
}

fn lab_settings_value(lab: &Lab) -> Value {
    serde_json::to_value(lab.settings()).unwrap_or_default()
}

/// An animal of the scene (now and then one past the last, to be refused),
/// or none.
fn selection(rng: &mut ChaCha8Rng, lab: &Lab) -> Value {
    let count = lab.runs()[0].animal_count();
    match rng.random_range(0..5) {
        0 => Value::Null,
        1 => json!(count),
        _ if count == 0 => Value::Null,
        _ => json!(rng.random_range(0..count)),
    }
}

/// Rocks: another seed's layout, none, or the seed's own (null).
fn obstacles(rng: &mut ChaCha8Rng) -> Value {
    match rng.random_range(0..3) {
        0 => serde_json::to_value(rocks_of(rng.random_range(0..1000))).unwrap_or_default(),
        1 => json!([]),
        _ => Value::Null,
    }
}

/// Is `p` in `tank`, within `tolerance_m`?
fn in_tank(tank: &Tank, p: Vec3, tolerance_m: f32) -> bool {
    let t = Vec3::splat(tolerance_m);
    p.cmpge(tank.min_m - t).all() && p.cmple(tank.max_m + t).all()
}

/// Checks every living animal of every tank of `lab` (see [`Violations`]);
/// returns how many animal-states it checked.
pub fn check(lab: &Lab, states: &mut Vec<AnimalState>, violations: &mut Violations) -> u64 {
    let mut checked = 0;
    for run in lab.runs() {
        let world = run.scene();
        let time = run.time_secs();
        world.living_states(states);
        checked += states.len() as u64;
        check_states(world.tank(), world.obstacles(), states, time, violations);
        let m = run.metrics();
        let numbers = [m.polarization, m.milling, m.nnd_body_lengths, m.mean_speed];
        if !(m.time_secs.is_finite() && numbers.iter().all(|x| x.is_finite())) {
            violations.metrics_not_finite += 1;
            violations.note(|| format!("t={time:.2} s metrics not finite: {m:?}"));
        }
    }
    checked
}

/// Checks `states` of animals in `tank` among `rocks` at simulated `time`.
pub fn check_states(
    tank: &Tank,
    rocks: &[Obstacle],
    states: &[AnimalState],
    time: f64,
    violations: &mut Violations,
) {
    for a in states {
        let nodes: &[Vec3] = a.nodes_m.as_ref().map_or(&[], |n| n.as_slice());
        let finite = a.position_m.is_finite()
            && a.velocity_m_per_s.is_none_or(|v| v.is_finite())
            && nodes.iter().all(|p| p.is_finite());
        if !finite {
            violations.not_finite += 1;
            violations.note(|| {
                format!(
                    "t={time:.2} s animal {}: not finite: at {:?}, velocity {:?}",
                    a.index, a.position_m, a.velocity_m_per_s
                )
            });
            continue;
        }
        let outside = !in_tank(tank, a.position_m, TOLERANCE_M)
            || nodes.iter().any(|&p| !in_tank(tank, p, TOLERANCE_M));
        if outside {
            violations.outside_tank += 1;
            violations.note(|| {
                format!(
                    "t={time:.2} s animal {}: outside the tank at {:?}",
                    a.index, a.position_m
                )
            });
        }
        let in_rock = rocks.iter().any(|o| {
            o.signed_distance_m(a.position_m) < -TOLERANCE_M
                || nodes
                    .iter()
                    .any(|&p| o.signed_distance_m(p) < -NODE_TOLERANCE_M)
        });
        if in_rock {
            violations.inside_rock += 1;
            violations.note(|| {
                format!(
                    "t={time:.2} s animal {}: inside a rock at {:?}",
                    a.index, a.position_m
                )
            });
        }
    }
}

/// What `shoal.soak_change(request)` asks for: the change number `index` of
/// the soak of `scene` with `seed`. `count_max` lowers the extremes' counts
/// (a page at 20,000 fish takes minutes a simulated minute);
/// `first_extremes_secs` moves the first block of extremes (default 60 s).
#[derive(Clone, Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChangeRequest {
    pub scene: Scene,
    pub seed: u64,
    pub index: u64,
    #[serde(default)]
    pub count_max: Option<u32>,
    #[serde(default)]
    pub random_count_max: Option<u32>,
    #[serde(default)]
    pub first_extremes_secs: Option<f64>,
}

impl ChangeRequest {
    /// The change, as `{what, call, arg, must_refuse}`: the page's script
    /// calls `shoal[call](arg)`.
    pub fn change(&self, lab: &Lab) -> Value {
        let mut config = SoakConfig::new(self.scene, 60.0, self.seed);
        config.extreme_count_max = self.count_max;
        if let Some(max) = self.random_count_max {
            config.random_count_max = max;
        }
        if let Some(secs) = self
            .first_extremes_secs
            .filter(|s| s.is_finite() && *s >= 0.0)
        {
            config.first_extremes_secs = secs;
        }
        let change = change_at(
            &config,
            &first_settings(self.scene, self.seed),
            lab,
            self.index,
        );
        let (call, arg) = change.call();
        json!({"what": change.what, "call": call, "arg": arg, "must_refuse": change.must_refuse})
    }
}

/// `shoal.soak_check()`: [`check`] on the page's lab, as
/// `{animals, not_finite, outside_tank, inside_rock, metrics_not_finite,
/// examples}`.
pub fn check_json(lab: &Lab) -> Value {
    let mut violations = Violations::default();
    let animals = check(lab, &mut Vec::new(), &mut violations);
    json!({
        "animals": animals,
        "not_finite": violations.not_finite,
        "outside_tank": violations.outside_tank,
        "inside_rock": violations.inside_rock,
        "metrics_not_finite": violations.metrics_not_finite,
        "examples": violations.examples,
    })
}

/// Is the refusal's message a reason a person reads: not empty, every
/// placeholder filled, and naming the setting when a setting was refused?
fn named(err: &AutomationError) -> bool {
    let text = err.to_string();
    let filled = !text.trim().is_empty() && !text.contains('{') && !text.contains("$");
    match err {
        AutomationError::Settings(SettingsError::Invalid(e)) => filled && text.contains(&e.key),
        AutomationError::Settings(SettingsError::UnknownKey { key, .. }) => {
            filled && text.contains(key.as_str())
        }
        _ => filled,
    }
}

/// What refused a change, for counting: the setting, or the kind of error.
fn refusal_kind(err: &AutomationError) -> String {
    match err {
        AutomationError::Settings(SettingsError::Invalid(e)) => format!("setting {}", e.key),
        AutomationError::Settings(SettingsError::UnknownKey { key, .. }) => {
            format!("unknown key {key}")
        }
        AutomationError::Settings(SettingsError::NotAnObject(_)) => "not an object".to_owned(),
        AutomationError::BadArgument(text) => {
            format!(
                "bad argument {}",
                text.split(':').next().unwrap_or_default()
            )
        }
        AutomationError::BadNumber { call, .. } => format!("bad number {call}"),
        AutomationError::Lab(e) => format!("lab {e:?}")
            .split('(')
            .next()
            .unwrap_or_default()
            .to_owned(),
        AutomationError::NotRunning => "not running".to_owned(),
    }
}

fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic without a message".to_owned())
}

/// Hears each change: simulated seconds, what, and the refusal if refused.
pub type OnChange<'a> = dyn FnMut(f64, &str, &Result<(), String>) + 'a;

/// A soak in progress: the lab, the changes' random numbers and the tally.
struct Soaker<'a> {
    lab: Lab,
    states: Vec<AnimalState>,
    report: SoakReport,
    on_change: &'a mut OnChange<'a>,
}

impl Soaker<'_> {
    /// Runs `secs` of simulated time, checking after every step.
    fn run(&mut self, secs: f64) -> Result<(), String> {
        let dt = self.lab.step_secs();
        let steps = (secs / dt).round().max(1.0) as u64;
        for _ in 0..steps {
            let lab = &mut self.lab;
            catch_unwind(AssertUnwindSafe(|| lab.step(1))).map_err(|p| panic_text(&*p))?;
            self.report.steps += 1;
            self.report.sim_secs += self.lab.step_secs();
            let animals: usize = self.lab.runs().iter().map(|r| r.animal_count()).sum();
            self.report.most_animals = self.report.most_animals.max(animals);
            self.report.animal_checks +=
                check(&self.lab, &mut self.states, &mut self.report.violations);
        }
        Ok(())
    }

    /// Applies `change`, then one frame of the app's clock.
    fn apply(&mut self, change: &Change) -> Result<(), String> {
        let lab = &mut self.lab;
        let command = change.command.clone();
        let result =
            catch_unwind(AssertUnwindSafe(|| command.execute(lab))).map_err(|p| panic_text(&*p))?;
        let outcome = match &result {
            Ok(()) => {
                self.report.changes_applied += 1;
                if change.must_refuse {
                    self.report
                        .accepted_bad_values
                        .push(format!("applied, should be refused: {}", change.what));
                }
                Ok(())
            }
            Err(err) => {
                self.report.changes_refused += 1;
                *self.report.refusals.entry(refusal_kind(err)).or_default() += 1;
                if !named(err) {
                    self.report
                        .unnamed_refusals
                        .push(format!("{}: refused as '{err}'", change.what));
                }
                Err(err.to_string())
            }
        };
        (self.on_change)(self.report.sim_secs, &change.what, &outcome);
        let lab = &mut self.lab;
        catch_unwind(AssertUnwindSafe(|| {
            lab.advance_frame(1.0 / 60.0, 0.0);
        }))
        .map_err(|p| panic_text(&*p))?;
        Ok(())
    }
}

/// The first settings of a soak of `scene`: the scene's own defaults, with
/// the soak's seed.
pub fn first_settings(scene: Scene, seed: u64) -> Settings {
    Settings {
        scene,
        seed,
        ..Settings::default()
    }
}

/// Runs the soak `config` describes. `heap_bytes` reads the heap in use (the
/// report's memory is `None` without it); `on_change` hears each change
/// (simulated seconds, what, and the refusal if refused).
pub fn soak(
    config: &SoakConfig,
    heap_bytes: &dyn Fn() -> Option<u64>,
    on_change: &mut OnChange<'_>,
) -> SoakReport {
    let started = web_time::Instant::now();
    let base = first_settings(config.scene, config.seed);
    let mut soaker = Soaker {
        lab: Lab::new(base.clone()),
        states: Vec::new(),
        report: SoakReport {
            scene: config.scene.name(),
            seed: config.seed,
            ..SoakReport::default()
        },
        on_change,
    };
    soaker.report.memory.start = heap_bytes();
    let outcome = (|| -> Result<(), String> {
        soaker.run(config.warm_up_secs)?;
        soaker.states = Vec::new();
        soaker.report.memory.after_warm_up = heap_bytes();
        let mut t = 0.0;
        let mut index = 0;
        while t < config.sim_secs {
            let change = change_at(config, &base, &soaker.lab, index);
            soaker.apply(&change)?;
            let secs = config.change_every_secs.min(config.sim_secs - t);
            soaker.run(secs)?;
            t += secs;
            index += 1;
        }
        // Back to the first settings, from the start, for the last reading.
        soaker.lab.apply_settings(base.clone());
        soaker.lab.reset(Some(base.seed));
        soaker.run(config.warm_up_secs)?;
        // The checker's own buffer held every animal of the largest school:
        // it is the soak's memory, not Shoal's.
        soaker.states = Vec::new();
        soaker.report.memory.end = heap_bytes();
        Ok(())
    })();
    soaker.report.panic = outcome.err();
    soaker.report.wall_secs = started.elapsed().as_secs_f64();
    soaker.report
}

#[cfg(test)]
mod tests;
