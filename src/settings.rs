//! Every setting a teacher can change, with its valid range, in one typed struct.
//!
//! The side panel edits a [`Settings`] directly; the automation API (`shoal.set({...})`
//! in the browser console, see `automation.rs`) patches it by the same field names
//! through [`Settings::apply_patch`], which either applies the whole patch or, on the
//! first unknown key, wrong type or out-of-range value, changes nothing and explains why.

use serde::{Deserialize, Serialize};

/// The scenes Shoal can show. Later issues add more (boids, physical fish, reef).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Scene {
    /// The first living scene: fish wandering through a tank with rocks and pillars.
    #[default]
    Aquarium,
}

impl Scene {
    pub const ALL: [Self; 1] = [Self::Aquarium];

    /// The name used in the UI and in the automation API.
    pub fn name(self) -> &'static str {
        match self {
            Self::Aquarium => "aquarium",
        }
    }

    /// A sentence a student understands.
    pub fn description(self) -> &'static str {
        match self {
            Self::Aquarium => "Fish wander through the tank and swim around rocks and pillars.",
        }
    }
}

/// Slowest simulation speed multiplier (a quarter of real time).
pub const SPEED_MIN: f32 = 0.25;
/// Fastest simulation speed multiplier (eight times real time).
pub const SPEED_MAX: f32 = 8.0;
/// Largest fish count a teacher can ask for. The renderer and the simulation stay
/// interactive well beyond the foundation's 200 fish.
pub const FISH_COUNT_MAX: u32 = 20_000;
/// Largest seed: JavaScript numbers are exact integers only up to 2^53 − 1, so seeds
/// stay within 32 bits to travel through JSON and URLs unchanged.
pub const SEED_MAX: u64 = u32::MAX as u64;

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
    /// Number of fish in the tank, from 0 to 20,000.
    pub fish_count: u32,
    /// Which scene is shown.
    pub scene: Scene,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            paused: false,
            seed: 1,
            speed: 1.0,
            fish_count: 200,
            scene: Scene::Aquarium,
        }
    }
}

/// Why a settings patch was refused. Nothing was changed.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum SettingsError {
    #[error("set() takes an object such as {{\"speed\": 2}}, not {0}")]
    NotAnObject(String),
    #[error("unknown setting '{key}'; the settings are: {known}")]
    UnknownKey { key: String, known: String },
    #[error("setting '{key}': {reason}")]
    Invalid { key: String, reason: String },
}

impl Settings {
    /// The names `apply_patch` accepts, in UI order.
    pub fn keys() -> Vec<String> {
        match serde_json::to_value(Self::default()) {
            Ok(serde_json::Value::Object(map)) => map.keys().cloned().collect(),
            _ => Vec::new(),
        }
    }

    /// Checks every range. Returns the first violation.
    pub fn validate(&self) -> Result<(), SettingsError> {
        let invalid = |key: &str, reason: String| {
            Err(SettingsError::Invalid {
                key: key.to_owned(),
                reason,
            })
        };
        if !(self.speed.is_finite() && (SPEED_MIN..=SPEED_MAX).contains(&self.speed)) {
            return invalid(
                "speed",
                format!(
                    "{} is out of range: choose from {SPEED_MIN} to {SPEED_MAX}",
                    self.speed
                ),
            );
        }
        if self.fish_count > FISH_COUNT_MAX {
            return invalid(
                "fish_count",
                format!(
                    "{} is out of range: choose from 0 to {FISH_COUNT_MAX}",
                    self.fish_count
                ),
            );
        }
        if self.seed > SEED_MAX {
            return invalid(
                "seed",
                format!("{} is out of range: choose from 0 to {SEED_MAX}", self.seed),
            );
        }
        Ok(())
    }

    /// Applies `patch` (a JSON object of setting names to values) all-or-nothing.
    pub fn apply_patch(&mut self, patch: &serde_json::Value) -> Result<(), SettingsError> {
        let serde_json::Value::Object(patch) = patch else {
            return Err(SettingsError::NotAnObject(patch.to_string()));
        };
        let serde_json::Value::Object(mut merged) = serde_json::to_value(&*self)
            .map_err(|err| SettingsError::NotAnObject(err.to_string()))?
        else {
            return Err(SettingsError::NotAnObject("settings".to_owned()));
        };
        for (key, value) in patch {
            if !merged.contains_key(key) {
                return Err(SettingsError::UnknownKey {
                    key: key.clone(),
                    known: Self::keys().join(", "),
                });
            }
            // Type-check each value on its own so the message names the setting.
            let mut single = merged.clone();
            single.insert(key.clone(), value.clone());
            if let Err(err) = serde_json::from_value::<Self>(serde_json::Value::Object(single)) {
                return Err(SettingsError::Invalid {
                    key: key.clone(),
                    reason: format!("{value} has the wrong type ({})", type_hint(&err)),
                });
            }
            merged.insert(key.clone(), value.clone());
        }
        let candidate: Self =
            serde_json::from_value(serde_json::Value::Object(merged)).map_err(|err| {
                SettingsError::Invalid {
                    key: "?".to_owned(),
                    reason: err.to_string(),
                }
            })?;
        candidate.validate()?;
        *self = candidate;
        Ok(())
    }
}

/// Shortens serde's message to the part a user needs ("expected a boolean").
fn type_hint(err: &serde_json::Error) -> String {
    let text = err.to_string();
    match text.find(", expected ") {
        Some(at) => text[at + 2..].to_owned(),
        None => text,
    }
    .split(" at line")
    .next()
    .unwrap_or_default()
    .to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn a_valid_patch_changes_exactly_the_named_settings() {
        let mut settings = Settings::default();
        settings
            .apply_patch(&json!({"speed": 2.0, "fish_count": 50, "paused": true}))
            .unwrap();
        assert_eq!(settings.speed, 2.0);
        assert_eq!(settings.fish_count, 50);
        assert!(settings.paused);
        assert_eq!(settings.seed, Settings::default().seed);
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
            err.to_string().contains("fish_count"),
            "lists the known keys: {err}"
        );
        assert_eq!(settings, Settings::default());
    }

    #[test]
    fn out_of_range_values_are_refused_and_change_nothing() {
        for patch in [
            json!({"speed": 9.0}),
            json!({"speed": 0.1}),
            json!({"fish_count": 20_001}),
            json!({"seed": 1u64 << 40}),
            json!({"fish_count": 10, "speed": 100}),
        ] {
            let mut settings = Settings::default();
            let err = settings.apply_patch(&patch).unwrap_err();
            assert!(err.to_string().contains("out of range"), "{patch}: {err}");
            assert_eq!(settings, Settings::default(), "{patch}");
        }
    }

    #[test]
    fn wrong_types_are_refused_with_the_setting_named() {
        for (patch, key) in [
            (json!({"paused": "yes"}), "paused"),
            (json!({"fish_count": -3}), "fish_count"),
            (json!({"fish_count": 2.5}), "fish_count"),
            (json!({"scene": "moon"}), "scene"),
            (json!({"speed": null}), "speed"),
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
    fn scene_names_round_trip() {
        for scene in Scene::ALL {
            let mut settings = Settings::default();
            settings
                .apply_patch(&json!({ "scene": scene.name() }))
                .unwrap();
            assert_eq!(settings.scene, scene);
        }
    }
}
