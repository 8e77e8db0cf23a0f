//! Every setting a teacher can change, with its valid range, in one typed struct.
//!
//! The side panel edits a [`Settings`] directly; the automation API (`shoal.set({...})`
//! in the browser console, see `automation.rs`) patches it by the same field names
//! through [`Settings::apply_patch`], which either applies the whole patch or, on the
//! first unknown key, wrong type or out-of-range value, changes nothing and explains why.

pub mod learning;
pub mod minds;
pub mod names;
pub mod number;
pub mod physics;
pub mod predation;
pub mod range;
pub mod reef;
pub mod share_link;
pub mod studio;
pub mod tank;

use serde::{Deserialize, Serialize};

use self::number::{Number, NumberSetting, Unit, Widget, field};
pub use self::range::{Range, SettingError};
use crate::settings::learning::LearningSettings;
use crate::settings::physics::PhysicsSettings;
pub use crate::settings::predation::PredationSettings;
use crate::settings::reef::ReefSettings;
use crate::settings::studio::Studio;
use crate::settings::tank::{Preset, TankSettings};
use crate::sim::Tank;
use crate::tr;

/// The scenes Shoal can show.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Scene {
    /// Fish wandering on their own through a tank with rocks and pillars.
    #[default]
    Aquarium,
    /// The SIMBA boid layer: five steering urges on sliders, control modes,
    /// sharks and stingrays, and the solo-versus-school comparison.
    Boids,
    /// Muscle-driven fish (Tu & Terzopoulos §3): spring–mass bodies that swim
    /// because their muscles contract against the water.
    Physics,
    /// Fish with minds (Tu & Terzopoulos §5–7): they see, get hungry, flee, school,
    /// hunt and court.
    Reef,
    /// Fish that learn to swim (Tu & Terzopoulos §4): simulated annealing of the
    /// muscle controls, their Fourier abstraction, the race, buoy tracking.
    Learning,
}

impl Scene {
    pub const ALL: [Self; 5] = [
        Self::Aquarium,
        Self::Boids,
        Self::Physics,
        Self::Reef,
        Self::Learning,
    ];

    /// The name used in the automation API and share links.
    pub fn name(self) -> &'static str {
        match self {
            Self::Aquarium => "aquarium",
            Self::Boids => "boids",
            Self::Physics => "physics",
            Self::Reef => "reef",
            Self::Learning => "learning",
        }
    }
}

/// Slowest simulation speed multiplier (a quarter of real time).
pub const SPEED_MIN: f32 = 0.25;
/// Fastest simulation speed multiplier (eight times real time).
pub const SPEED_MAX: f32 = 8.0;
pub use crate::settings::tank::FISH_COUNT_MAX;
/// Largest seed: JavaScript numbers are exact integers only up to 2^53 − 1, so seeds
/// stay within 32 bits to travel through JSON and URLs unchanged.
pub const SEED_MAX: u64 = u32::MAX as u64;

/// Which of the two tanks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Side {
    /// The only tank when not comparing.
    #[default]
    Left,
    Right,
}

impl Side {
    pub const BOTH: [Self; 2] = [Self::Left, Self::Right];

    /// The settings key (`left`, `right`).
    pub fn name(self) -> &'static str {
        match self {
            Self::Left => "left",
            Self::Right => "right",
        }
    }

    /// The prefix of the tank's keys in `shoal.set`, error messages and the
    /// studio's rules (`left.`).
    pub fn prefix(self) -> String {
        format!("{}.", self.name())
    }

    pub fn index(self) -> usize {
        self as usize
    }
}

/// What the teacher controls. Field names are the automation API's names.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Settings {
    /// Is the simulation stopped? Drawing goes on while paused.
    pub paused: bool,
    /// Seed of the world's random number generator: the same seed gives the same run.
    pub seed: u64,
    /// Simulated seconds per real second, from 0.25 to 8.
    pub speed: f32,
    /// Which scene is shown.
    pub scene: Scene,
    /// Two tanks side by side (boid scene), same seed and starting positions.
    pub compare: bool,
    /// Draw each fish's field of view and lines to the neighbours it sees.
    pub show_vision: bool,
    /// The tank (the left one when comparing). The aquarium scene uses its
    /// `fish_count` only.
    pub left: TankSettings,
    /// The right tank when comparing.
    pub right: TankSettings,
    /// The physics fish scene. Links made before this scene existed lack it and
    /// get the defaults.
    #[serde(default)]
    pub physics: PhysicsSettings,
    /// The reef scene (fish with minds). Links made before it existed lack it.
    #[serde(default)]
    pub reef: ReefSettings,
    /// The learning lab. Links made before it existed lack it.
    #[serde(default)]
    pub learning: LearningSettings,
    /// The confusion effect and joint flight, in the schooling lab and the
    /// reef. Links made before the switches existed lack them (both on).
    #[serde(default)]
    pub predation: PredationSettings,
    /// The teacher's studio: which controls students see, may change and may
    /// read, and the teacher's question (`studio.rs`). Links made before it
    /// existed lack it, and a setting without rules, question or student view
    /// leaves it out (its links are those of before the studio).
    #[serde(default, skip_serializing_if = "Studio::is_empty")]
    pub studio: Studio,
}

impl Default for Settings {
    /// The aquarium scene; in the boid scene the left tank starts "Individual" and
    /// the right one "Group", the comparison the lesson is about.
    fn default() -> Self {
        Self {
            paused: false,
            seed: 1,
            speed: 1.0,
            scene: Scene::default(),
            compare: false,
            show_vision: false,
            left: TankSettings::with_preset(Preset::Individual),
            right: TankSettings::with_preset(Preset::Group),
            physics: PhysicsSettings::default(),
            reef: ReefSettings::default(),
            learning: LearningSettings::default(),
            predation: PredationSettings::default(),
            studio: Studio::default(),
        }
    }
}

/// Why a settings patch was refused. Nothing was changed. (Its Display is
/// the catalogue's `setting-error-…`.)
#[derive(Debug, PartialEq)]
pub enum SettingsError {
    NotAnObject(String),
    UnknownKey { key: String, known: String },
    Invalid(SettingError),
}

impl From<SettingError> for SettingsError {
    fn from(err: SettingError) -> Self {
        Self::Invalid(err)
    }
}

impl std::fmt::Display for SettingsError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NotAnObject(value) => {
                f.write_str(&tr!("setting-error-not-an-object", value = value.as_str()))
            }
            Self::UnknownKey { key, known } => f.write_str(&tr!(
                "setting-error-unknown-key",
                key = key.as_str(),
                known = known.as_str()
            )),
            Self::Invalid(err) => err.fmt(f),
        }
    }
}

impl std::error::Error for SettingsError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Invalid(err) => err.source(),
            _ => None,
        }
    }
}

impl Settings {
    /// The top-level names `apply_patch` accepts, in UI order.
    pub fn keys() -> Vec<String> {
        keys_of(&Self::default())
    }

    /// The animal selected in the scene on show (by index), if the scene
    /// lets one pick an animal. In the schooling lab, the (left) tank's fish;
    /// [`Self::selected_in`] gives each tank's.
    pub fn selected(&self) -> Option<u32> {
        self.selected_in(Side::Left)
    }

    /// The animal selected in the tank of `side` (only the schooling lab's
    /// right tank, when comparing, differs from [`Self::selected`]).
    pub fn selected_in(&self, side: Side) -> Option<u32> {
        self.scene.class().selected(self, side)
    }

    /// The tank settings of `side`.
    pub fn tank(&self, side: Side) -> &TankSettings {
        match side {
            Side::Left => &self.left,
            Side::Right => &self.right,
        }
    }

    /// Mutable tank settings of `side`.
    pub fn tank_mut(&mut self, side: Side) -> &mut TankSettings {
        match side {
            Side::Left => &mut self.left,
            Side::Right => &mut self.right,
        }
    }

    /// Simulated seconds per real second.
    pub const SPEED: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "app",
        Range::or_else("speed", SPEED_MIN, SPEED_MAX, 1.0),
        field!(speed),
    )
    .unit(Unit::Times)
    .widget(Widget::Slider {
        logarithmic: true,
        decimals: Some(2),
    });
    /// The world's seed (typed in, or a new one from the *New* button beside it).
    pub const SEED: NumberSetting<Self, u64> =
        NumberSetting::<Self, _>::new("app", Range::new("seed", 0, SEED_MAX), field!(seed)).widget(
            Widget::Field {
                drag_speed: 1.0,
                own_help: true,
            },
        );
    /// Every numeric setting at the top level (each scene's are in its own
    /// settings' table).
    pub const NUMBERS: [Number<Self>; 2] = [Number::F32(Self::SPEED), Number::U64(Self::SEED)];

    /// Checks every range. Returns the first violation.
    pub fn validate(&self) -> Result<(), SettingsError> {
        number::check_all(&Self::NUMBERS, "", self)?;
        let tank = Tank::default();
        for side in Side::BOTH {
            self.tank(side).validate(&side.prefix(), &tank)?;
        }
        self.physics.validate(PhysicsSettings::PREFIX)?;
        self.reef.validate(ReefSettings::PREFIX)?;
        self.learning.validate(LearningSettings::PREFIX)?;
        self.studio.validate()?;
        Ok(())
    }

    /// Brings every value into range (for paths that cannot refuse).
    pub fn clamp(&mut self) {
        number::clamp_all(&Self::NUMBERS, self);
        let tank = Tank::default();
        self.left.clamp(&tank);
        self.right.clamp(&tank);
        self.physics.clamp();
        self.reef.clamp();
        self.learning.clamp();
    }

    /// Makes each tank's preset label true after an edit (see
    /// [`TankSettings::settle`]).
    pub fn settle(&mut self, before: &Self) {
        self.left.settle(&before.left);
        self.right.settle(&before.right);
    }

    /// Applies `patch` (a JSON object of setting names to values) all-or-nothing.
    /// Nested objects merge: `{"left": {"cohesion": 40}}` changes one slider of the
    /// left tank and keeps the rest.
    pub fn apply_patch(&mut self, patch: &serde_json::Value) -> Result<(), SettingsError> {
        let serde_json::Value::Object(patch) = patch else {
            return Err(SettingsError::NotAnObject(patch.to_string()));
        };
        // The studio's rules are keyed by control, not fixed names: its part
        // is checked by its own rules (`Studio::apply_patch`).
        let mut patch = patch.clone();
        let studio_patch = patch.remove("studio");
        let patch = &patch;
        // A preset named in the patch is applied first, then the patch's values on
        // top of it: `{"left": {"preset": "group", "alignment": 40}}` gives the
        // group's weights with alignment 40 (and the label Custom), never a
        // silently dropped value.
        let mut base = self.clone();
        for side in Side::BOTH {
            let preset = patch
                .get(side.name())
                .and_then(|tank| tank.get("preset"))
                .and_then(|preset| serde_json::from_value::<Preset>(preset.clone()).ok());
            if let Some(preset) = preset {
                base.tank_mut(side).load_preset(preset);
            }
        }
        let mut merged = serde_json::to_value(&base)
            .map_err(|err| SettingsError::NotAnObject(err.to_string()))?;
        merge_checked(&mut merged, &[], patch)?;
        let mut candidate: Self = serde_json::from_value(merged).map_err(|err| SettingError {
            key: "?".to_owned(),
            reason: err.to_string(),
        })?;
        candidate.let_go_of_unnamed(&base, patch);
        if let Some(studio) = &studio_patch {
            candidate.studio.apply_patch(studio)?;
        }
        candidate.validate()?;
        candidate.settle(&base);
        *self = candidate;
        Ok(())
    }
}

impl Settings {
    /// After a patch: what the patch changed brings along what the panel
    /// would change with it, for the values the patch does not name. A fish
    /// selected in a tank, or among the physics fish, that a smaller count
    /// leaves out is let go (and with it the hand control and the camera on
    /// it); a new reef demo is chosen as its button chooses it (its own
    /// counts, its own selection), so a demo can be chosen whatever was
    /// selected before.
    fn let_go_of_unnamed(
        &mut self,
        before: &Self,
        patch: &serde_json::Map<String, serde_json::Value>,
    ) {
        let named =
            |part: &str, key: &str| patch.get(part).and_then(|part| part.get(key)).is_some();
        for side in Side::BOTH {
            if !named(side.name(), "selected") {
                let tank = self.tank_mut(side);
                tank.selected = tank.selected.filter(|&i| i < tank.fish_count);
            }
        }
        let physics = &mut self.physics;
        if !named("physics", "selected")
            && physics
                .selected
                .is_some_and(|i| i >= physics.animal_count())
        {
            physics.selected = None;
            if !named("physics", "hand_control") {
                physics.hand_control = false;
            }
            if !named("physics", "follow") {
                physics.follow = false;
            }
        }
        if self.reef.demo != before.reef.demo {
            let mut chosen = before.reef.clone();
            chosen.choose_demo(self.reef.demo);
            let reef = &mut self.reef;
            if !named("reef", "prey_count") {
                reef.prey_count = chosen.prey_count;
            }
            if !named("reef", "food_count") {
                reef.food_count = chosen.food_count;
            }
            if !named("reef", "selected") {
                reef.selected = chosen.selected;
            }
            if !named("reef", "follow") {
                reef.follow = chosen.follow;
            }
        }
        let reef = &mut self.reef;
        if !named("reef", "selected")
            && reef
                .selected
                .is_some_and(|i| i as usize >= reef.animal_count())
        {
            reef.selected = None;
            if !named("reef", "follow") {
                reef.follow = false;
            }
        }
    }
}

/// The keys of a serialised value's top level.
fn keys_of(value: &impl Serialize) -> Vec<String> {
    match serde_json::to_value(value) {
        Ok(serde_json::Value::Object(map)) => map.keys().cloned().collect(),
        _ => Vec::new(),
    }
}

/// Merges `patch` into the object at `path` of `root`, checking each key exists and
/// each value has a type `Settings` accepts, so the message names the setting.
fn merge_checked(
    root: &mut serde_json::Value,
    path: &[String],
    patch: &serde_json::Map<String, serde_json::Value>,
) -> Result<(), SettingsError> {
    for (key, value) in patch {
        let mut full_path = path.to_vec();
        full_path.push(key.clone());
        let dotted = full_path.join(".");
        let Some(current) = value_at(root, &full_path) else {
            let parent = value_at(root, path).cloned().unwrap_or_default();
            let known = match parent {
                serde_json::Value::Object(map) => map.keys().cloned().collect::<Vec<_>>(),
                _ => Vec::new(),
            };
            return Err(SettingsError::UnknownKey {
                key: dotted,
                known: known.join(", "),
            });
        };
        match (current, value) {
            (serde_json::Value::Object(_), serde_json::Value::Object(inner)) => {
                merge_checked(root, &full_path, inner)?;
            }
            _ => {
                let mut single = root.clone();
                if let Some(slot) = value_at_mut(&mut single, &full_path) {
                    *slot = value.clone();
                }
                if let Err(err) = serde_json::from_value::<Settings>(single) {
                    return Err(SettingError {
                        key: dotted,
                        reason: tr!(
                            "setting-error-wrong-type",
                            value = value.to_string(),
                            hint = type_hint(&err)
                        ),
                    }
                    .into());
                }
                if let Some(slot) = value_at_mut(root, &full_path) {
                    *slot = value.clone();
                }
            }
        }
    }
    Ok(())
}

fn value_at<'a>(root: &'a serde_json::Value, path: &[String]) -> Option<&'a serde_json::Value> {
    path.iter().try_fold(root, |v, key| v.as_object()?.get(key))
}

fn value_at_mut<'a>(
    root: &'a mut serde_json::Value,
    path: &[String],
) -> Option<&'a mut serde_json::Value> {
    path.iter()
        .try_fold(root, |v, key| v.as_object_mut()?.get_mut(key))
}

/// Shortens serde's message to the part a user needs ("expected a boolean").
fn type_hint(err: &serde_json::Error) -> String {
    let text = err.to_string();
    match text.find(", expected ") {
        Some(at) => text[at + 2..].to_owned(),
        None => text,
    }
    .split(" at line") // words: cut from serde's message, not shown
    .next()
    .unwrap_or_default()
    .to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::boids::control_mode::{ControlMode, GROUP_WEIGHTS};
    use serde_json::json;

    #[test]
    fn a_valid_patch_changes_exactly_the_named_settings() {
        let mut settings = Settings::default();
        settings
            .apply_patch(&json!({"speed": 2.0, "left": {"fish_count": 50}, "paused": true}))
            .unwrap();
        assert_eq!(settings.speed, 2.0);
        assert_eq!(settings.left.fish_count, 50);
        assert!(settings.paused);
        assert_eq!(settings.seed, Settings::default().seed);
        assert_eq!(settings.right, Settings::default().right);
    }

    #[test]
    fn a_patch_with_a_preset_and_a_value_applies_the_preset_then_the_value() {
        let mut settings = Settings::default();
        settings
            .apply_patch(&json!({"left": {"preset": "group", "alignment": 40}}))
            .unwrap();
        assert_eq!(
            settings.left.alignment, 40.0,
            "the value is kept, not dropped"
        );
        assert_eq!(
            settings.left.cohesion, GROUP_WEIGHTS[2],
            "the preset applied"
        );
        assert_eq!(settings.left.separation, GROUP_WEIGHTS[3]);
        assert_eq!(
            settings.left.preset,
            Preset::Custom,
            "the label tells the truth"
        );
        // The preset's own value with it keeps the preset's name.
        settings
            .apply_patch(&json!({"left": {"preset": "individual", "cohesion": 0}}))
            .unwrap();
        assert_eq!(settings.left.preset, Preset::Individual);
        // A preset and a mode: the paper partition with its mode, then the mode asked.
        settings
            .apply_patch(&json!({"right": {"preset": "monte_carlo_paper", "mode": "classic"}}))
            .unwrap();
        assert_eq!(settings.right.mode, ControlMode::Classic);
        assert_eq!(settings.right.preset, Preset::Custom);
    }

    #[test]
    fn the_compared_tanks_differ_only_in_the_five_weights() {
        let settings = Settings::default();
        let (mut left, right) = (settings.left.clone(), settings.right.clone());
        assert_ne!(left.weights(), right.weights());
        left.preset = right.preset;
        left.containment = right.containment;
        left.alignment = right.alignment;
        left.cohesion = right.cohesion;
        left.separation = right.separation;
        left.avoidance = right.avoidance;
        assert_eq!(left, right, "every other setting is the same");
    }

    #[test]
    fn nested_patches_merge_and_keep_the_preset_label_true() {
        let mut settings = Settings::default();
        settings
            .apply_patch(&json!({"right": {"cohesion": 80}}))
            .unwrap();
        assert_eq!(settings.right.cohesion, 80.0);
        assert_eq!(settings.right.alignment, GROUP_WEIGHTS[1]);
        assert_eq!(settings.right.preset, Preset::Custom);
        settings
            .apply_patch(&json!({"right": {"preset": "group", "mode": "monte_carlo"}}))
            .unwrap();
        assert_eq!(settings.right.weights(), GROUP_WEIGHTS);
        assert_eq!(settings.right.mode, ControlMode::MonteCarlo);
        assert_eq!(settings.right.preset, Preset::Group);
    }

    #[test]
    fn an_unknown_key_is_refused_and_changes_nothing() {
        let mut settings = Settings::default();
        let err = settings
            .apply_patch(&json!({"speed": 2.0, "fishcount": 5}))
            .unwrap_err();
        assert!(
            err.to_string().contains("unknown setting 'fishcount'"),
            "{err}"
        );
        assert!(
            err.to_string().contains("left"),
            "lists the known keys: {err}"
        );
        assert_eq!(settings, Settings::default());
        let err = settings
            .apply_patch(&json!({"left": {"cohesio": 5}}))
            .unwrap_err();
        assert!(err.to_string().contains("'left.cohesio'"), "{err}");
        assert!(err.to_string().contains("cohesion"), "{err}");
    }

    #[test]
    fn out_of_range_values_are_refused_and_change_nothing() {
        for (patch, key) in [
            (json!({"speed": 9.0}), "speed"),
            (json!({"speed": 0.1}), "speed"),
            (json!({"left": {"fish_count": 20_001}}), "left.fish_count"),
            (json!({"seed": 1u64 << 40}), "seed"),
            (json!({"right": {"alignment": 100.5}}), "right.alignment"),
            (
                json!({"right": {"vision_angle_deg": -1}}),
                "right.vision_angle_deg",
            ),
            (json!({"left": {"sharks": 99}}), "left.sharks"),
        ] {
            let mut settings = Settings::default();
            let err = settings.apply_patch(&patch).unwrap_err();
            assert!(err.to_string().contains("out of range"), "{patch}: {err}");
            assert!(err.to_string().contains(&format!("'{key}'")), "{err}");
            assert_eq!(settings, Settings::default(), "{patch}");
        }
    }

    #[test]
    fn wrong_types_are_refused_with_the_setting_named() {
        for (patch, key) in [
            (json!({"paused": "yes"}), "paused"),
            (json!({"left": {"fish_count": -3}}), "left.fish_count"),
            (json!({"left": {"fish_count": 2.5}}), "left.fish_count"),
            (json!({"scene": "moon"}), "scene"),
            (json!({"speed": null}), "speed"),
            (json!({"left": 3}), "left"),
            (json!({"right": {"mode": "telepathy"}}), "right.mode"),
        ] {
            let mut settings = Settings::default();
            let err = settings.apply_patch(&patch).unwrap_err();
            assert!(
                err.to_string().starts_with(&format!("setting '{key}'")),
                "{err}"
            );
            assert_eq!(settings, Settings::default());
        }
    }

    #[test]
    fn a_patch_must_be_an_object() {
        let mut settings = Settings::default();
        assert!(matches!(
            settings.apply_patch(&json!([1, 2])),
            Err(SettingsError::NotAnObject(_))
        ));
    }

    #[test]
    fn a_demo_is_chosen_through_set_whatever_fish_was_selected() {
        // After a skip the reef's moment fish stays selected and followed;
        // choosing another demo with fewer animals let go of it, as the
        // demo's button does, instead of refusing the demo.
        let mut settings = Settings::default();
        settings
            .apply_patch(&json!({"scene": "reef", "reef": {"demo": "predator_and_school"}}))
            .unwrap();
        let last = settings.reef.animal_count() as u32 - 1;
        settings
            .apply_patch(&json!({"reef": {"selected": last, "follow": true, "prey_count": 30}}))
            .unwrap();
        for demo in ["courtship", "feeding", "school_meets_obstacle", "reef"] {
            let mut s = settings.clone();
            s.apply_patch(&json!({"reef": {"demo": demo}})).unwrap();
            let mut by_button = settings.reef.clone();
            by_button.choose_demo(s.reef.demo);
            assert_eq!(s.reef, by_button, "{demo}");
        }
        // What the patch names, it keeps; a selection the new demo has no
        // fish for is still refused, by name.
        let mut s = settings.clone();
        s.apply_patch(&json!({"reef": {"demo": "reef", "prey_count": 12, "selected": 3}}))
            .unwrap();
        assert_eq!((s.reef.prey_count, s.reef.selected), (Some(12), Some(3)));
        let err = settings
            .clone()
            .apply_patch(&json!({"reef": {"demo": "courtship", "selected": 90}}))
            .unwrap_err();
        assert!(err.to_string().contains("reef.selected"), "{err}");
        // The physics fish: a smaller count lets go of the fish and of the
        // hand control on it.
        let mut s = Settings::default();
        s.apply_patch(&json!({"physics": {"fish_count": 6, "selected": 5, "hand_control": true}}))
            .unwrap();
        s.apply_patch(&json!({"physics": {"fish_count": 3}}))
            .unwrap();
        assert_eq!((s.physics.selected, s.physics.hand_control), (None, false));
    }

    #[test]
    fn scene_names_round_trip() {
        for scene in Scene::ALL {
            let mut settings = Settings::default();
            settings
                .apply_patch(&json!({ "scene": scene.name() }))
                .unwrap();
            assert_eq!(settings.scene, scene);
        }
    }

    #[test]
    fn the_default_comparison_is_individual_against_group() {
        let settings = Settings::default();
        assert_eq!(settings.left.preset, Preset::Individual);
        assert_eq!(settings.right.preset, Preset::Group);
        assert!(settings.validate().is_ok());
    }

    #[test]
    fn every_range_refuses_a_value_just_outside_and_clamps_it_to_the_bound() {
        number::check_table(
            &Settings::default(),
            "",
            &Settings::NUMBERS,
            |s| match s.validate() {
                Err(SettingsError::Invalid(err)) => Err(err),
                other => {
                    assert_eq!(other, Ok(()));
                    Ok(())
                }
            },
            Settings::clamp,
        );
    }
}
