//! Each setting named from its key (`left.alignment`, `reef.traits.prey.
//! fear_threshold`, `physics.show_body`) as the side panel names it
//! ("Alignment", "Show masses and springs"), in the language in force, with its
//! unit and, for a number, its slider's range ([`setting_name`]). The views
//! that name a setting out of its panel use it: the Experiment window (its
//! factors, table, axes and legends) and the studio's rules. The keys stay
//! what programs read (the design file, the CSV, the links); only the words
//! on screen come from here.

use super::learning::LearningSettings;
use super::number::{Number, Widget};
use super::physics::PhysicsSettings;
use super::reef::ReefSettings;
use super::tank::TankSettings;
use super::{Settings, Side};
use crate::i18n::ts;
use crate::sim::reef::mind::FishKind;
use crate::sim::reef::mind::habits::MindTraits;
use crate::tr;

/// What an experiment needs of a number's slider: its range, whether it
/// holds whole numbers, whether it spans orders of magnitude.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slider {
    pub min: f64,
    pub max: f64,
    pub whole: bool,
    /// A logarithmic slider, or a count up to thousands: a range over orders
    /// of magnitude.
    pub wide: bool,
}

/// A setting's words and, for a number, its slider.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SettingName {
    /// Its label on the side panel ("Alignment").
    pub label: &'static str,
    /// What follows its number, with its space (" m/s", "°"); empty for a
    /// plain number or a setting that is not a number.
    pub unit: &'static str,
    /// The tank it belongs to (`left.`, `right.`).
    pub side: Option<Side>,
    /// The kind of fish whose mind it changes (`reef.traits.prey.`).
    pub kind: Option<FishKind>,
    /// The slider's range, for a number.
    pub slider: Option<Slider>,
}

impl SettingName {
    /// Its name out of its panel: the label, the kind of fish it is about, and,
    /// when `with_side`, its tank ("Alignment (left tank)").
    pub fn text(&self, with_side: bool) -> String {
        self.words(with_side, "")
    }

    /// [`Self::text`] with its unit, as a plot's axis or a table's column
    /// names it ("Vision distance (m)", "Top speed (m/s, left tank)"; no
    /// brackets for a plain number).
    pub fn text_with_unit(&self, with_side: bool) -> String {
        self.words(with_side, self.unit.trim())
    }

    fn words(&self, with_side: bool, unit: &str) -> String {
        let label = match self.kind {
            Some(kind) => tr!(
                "setting-name-kind",
                label = self.label,
                kind = kind_words(kind)
            ),
            None => self.label.to_owned(),
        };
        let side = self.side.filter(|_| with_side);
        match (side, unit.is_empty()) {
            (None, true) => label,
            (None, false) => tr!("setting-name-unit", label = label, unit = unit),
            (Some(Side::Left), true) => tr!("setting-name-left", label = label),
            (Some(Side::Right), true) => tr!("setting-name-right", label = label),
            (Some(Side::Left), false) => tr!("setting-name-left-unit", label = label, unit = unit),
            (Some(Side::Right), false) => {
                tr!("setting-name-right-unit", label = label, unit = unit)
            }
        }
    }
}

/// A kind of fish as the *Minds* section's buttons name it ("Prey fish").
fn kind_words(kind: FishKind) -> &'static str {
    match kind {
        FishKind::Predator => ts("reef-minds-sharks"),
        FishKind::Prey => ts("reef-minds-prey"),
        FishKind::Pacifist => ts("reef-minds-pacifists"),
    }
}

/// The words of `key`, a setting as `shoal.set`, share links, experiment
/// designs and the studio's rules name it; `None` for a key that is not a
/// setting (or a group of them, such as `left`).
pub fn setting_name(key: &str) -> Option<SettingName> {
    let (side, rest) = match key.split_once('.') {
        Some((s, rest)) if s == Side::Left.name() => (Some(Side::Left), rest),
        Some((s, rest)) if s == Side::Right.name() => (Some(Side::Right), rest),
        _ => (None, key),
    };
    if let Some(side) = side {
        let mut name = in_table(&TankSettings::NUMBERS, rest).or_else(|| {
            other(match rest {
                "preset" => "setting-tank-panel-preset",
                "mode" => "setting-tank-panel-mode",
                "obstacles" => "boids-rocks",
                "selected" => "setting-name-selected",
                _ => return None,
            })
        })?;
        name.side = Some(side);
        return Some(name);
    }
    if let Some(rest) = key.strip_prefix(PhysicsSettings::PREFIX) {
        return in_table(&PhysicsSettings::NUMBERS, rest).or_else(|| {
            other(match rest {
                "behaviour" => "setting-name-physics-behaviour",
                "selected" => "setting-name-selected",
                "hand_control" => "physics-hand",
                "follow" => "physics-follow",
                "show_body" => "physics-show-body",
                "show_forces" => "physics-show-forces",
                _ => return None,
            })
        });
    }
    if let Some(rest) = key.strip_prefix(ReefSettings::PREFIX) {
        if let Some(traits) = rest.strip_prefix("traits.") {
            let (kind, name) = traits.split_once('.')?;
            let kind = FishKind::ALL.into_iter().find(|k| k.label() == kind)?;
            let mut name = in_table(&MindTraits::NUMBERS, name)?;
            name.kind = Some(kind);
            return Some(name);
        }
        return in_table(&ReefSettings::NUMBERS, rest).or_else(|| {
            other(match rest {
                "demo" => "setting-name-reef-demo",
                "body" => "reef-body",
                "selected" => "setting-name-selected",
                "follow" => "reef-follow",
                "show_vision" => "reef-show-vision",
                "overlay" => "reef-show-water",
                "name_tags" => "reef-name-tags",
                _ => return None,
            })
        });
    }
    if let Some(rest) = key.strip_prefix(crate::settings::PredationSettings::PREFIX) {
        return other(match rest {
            "confusion" => "predation-confusion",
            "joint_flight" => "predation-joint-flight",
            _ => return None,
        });
    }
    if let Some(rest) = key.strip_prefix(LearningSettings::PREFIX) {
        return in_table(&LearningSettings::NUMBERS, rest).or_else(|| {
            other(match rest {
                "species" => "learning-learner",
                "training" => "setting-name-learning-training",
                "controller" => "setting-name-learning-controller",
                _ => return None,
            })
        });
    }
    in_table(&Settings::NUMBERS, key).or_else(|| {
        other(match key {
            "paused" => "setting-name-paused",
            "scene" => "setting-name-scene",
            "compare" => "boids-compare",
            "show_vision" => "boids-show-vision",
            _ => return None,
        })
    })
}

/// `key`'s name as [`SettingName::text`] gives it; the key itself for one
/// that is not a setting (never for a key the engine accepts: a test walks
/// them all).
pub fn setting_text(key: &str, with_side: bool) -> String {
    setting_name(key).map_or_else(|| key.to_owned(), |n| n.text(with_side))
}

/// A setting that is not a number, named by the catalogue's `id`.
fn other(id: &'static str) -> Option<SettingName> {
    Some(SettingName {
        label: ts(id),
        unit: "",
        side: None,
        kind: None,
        slider: None,
    })
}

/// The number `key` of `table`, named by its own entry.
fn in_table<S>(table: &[Number<S>], key: &str) -> Option<SettingName> {
    let number = table.iter().find(|n| n.key() == key)?;
    let (label, unit, widget, min, max, whole) = match number {
        Number::F32(s) => (
            s.label(),
            s.unit_text(),
            s.widget,
            f64::from(s.range.min),
            f64::from(s.range.max),
            false,
        ),
        Number::U32(s) => (
            s.label(),
            s.unit_text(),
            s.widget,
            f64::from(s.range.min),
            f64::from(s.range.max),
            true,
        ),
        Number::U64(s) => (
            s.label(),
            s.unit_text(),
            s.widget,
            s.range.min as f64,
            s.range.max as f64,
            true,
        ),
    };
    let logarithmic = matches!(
        widget,
        Widget::Slider {
            logarithmic: true,
            ..
        }
    );
    Some(SettingName {
        label,
        unit,
        side: None,
        kind: None,
        slider: Some(Slider {
            min,
            max,
            whole,
            wide: logarithmic || (whole && max >= 1000.0),
        }),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::{Lang, has, with_lang};
    use serde_json::Value;

    /// Every setting's key (every leaf of the settings but the studio's).
    fn every_key() -> Vec<String> {
        fn leaves(prefix: &str, value: &Value, out: &mut Vec<String>) {
            match value {
                Value::Object(map) => {
                    for (k, v) in map {
                        let key = if prefix.is_empty() {
                            k.clone()
                        } else {
                            format!("{prefix}.{k}")
                        };
                        leaves(&key, v, out);
                    }
                }
                _ => out.push(prefix.to_owned()),
            }
        }
        let mut keys = Vec::new();
        let value = serde_json::to_value(Settings::default()).expect("settings serialise");
        leaves("", &value, &mut keys);
        keys.retain(|k| !k.starts_with("studio"));
        keys
    }

    #[test]
    fn every_setting_has_a_name_in_every_language_and_never_shows_its_key() {
        let keys = every_key();
        assert!(keys.len() > 60, "{keys:?}");
        for lang in Lang::ALL {
            with_lang(lang, || {
                for key in &keys {
                    let name = setting_name(key).unwrap_or_else(|| panic!("{key} has a name"));
                    for text in [name.text(true), name.text_with_unit(true)] {
                        assert!(!text.is_empty() && !text.contains('['), "{key}: {text}");
                        assert!(!text.contains('_') && !text.contains(key), "{key}: {text}");
                    }
                }
            });
        }
        for id in [
            "setting-name-kind",
            "setting-name-left",
            "setting-name-right",
            "setting-name-unit",
            "setting-name-left-unit",
            "setting-name-right-unit",
        ] {
            for lang in Lang::ALL {
                assert!(has(lang, id), "{id} in {lang:?}");
            }
        }
        assert_eq!(setting_name("left"), None, "a group of settings");
        assert_eq!(setting_name("left.alignmnt"), None);
    }

    #[test]
    fn names_read_as_the_panel_reads_them_with_the_tank_and_the_kind() {
        let alignment = setting_name("left.alignment").expect("a setting");
        assert_eq!(alignment.text(false), "Alignment");
        assert_eq!(alignment.text(true), "Alignment (left tank)");
        assert_eq!(
            alignment.slider,
            Some(Slider {
                min: 0.0,
                max: 100.0,
                whole: false,
                wide: false
            })
        );
        assert_eq!(
            setting_text("right.vision_distance_m", true),
            "Vision distance (right tank)"
        );
        assert_eq!(
            setting_name("left.vision_distance_m")
                .expect("a setting")
                .text_with_unit(true),
            "Vision distance (m, left tank)"
        );
        assert_eq!(
            setting_text("reef.traits.prey.fear_distance_body_lengths", true),
            "Prey fish · Fear distance (D0)"
        );
        assert!(
            setting_name("left.fish_count")
                .expect("a count")
                .slider
                .expect("a slider")
                .wide
        );
        with_lang(Lang::Es, || {
            assert_eq!(
                setting_text("left.alignment", true),
                "Alineación (tanque izquierdo)"
            );
            assert_eq!(
                setting_name("physics.current_m_per_s")
                    .expect("a setting")
                    .text_with_unit(false),
                "Corriente (m/s)"
            );
        });
    }
}
