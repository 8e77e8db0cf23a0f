//! The settings of the "Learning lab" scene (`Settings::learning`): who learns
//! (a fish or a shark), how long each drill is practised, whether training runs,
//! and which controllers drive the demo fish. Field names are the automation
//! API's names (`shoal.set({learning: {training: true}})`).

use serde::{Deserialize, Serialize};

use crate::settings::number::{Number, NumberSetting, Widget, check_all, clamp_all, field};
use crate::settings::range::{Range, SettingError};
use crate::sim::BodySpecies;
use crate::sim::learning::learning_lab::ControllerChoice;

/// Fewest annealing steps per drill the slider offers (Fig. 7's least-trained shark).
pub const ANNEALING_STEPS_MIN: u32 = 90;
/// Most annealing steps per drill (three times Fig. 7's best shark).
pub const ANNEALING_STEPS_MAX: u32 = 20_000;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LearningSettings {
    /// Who learns: `"fish"` or `"shark"`.
    pub species: BodySpecies,
    /// Annealing steps (forward simulations) per drill, [`ANNEALING_STEPS_MIN`] to
    /// [`ANNEALING_STEPS_MAX`]. Default 6840, Fig. 7's best-trained shark.
    pub annealing_steps: u32,
    /// Is training running (a little every frame)?
    pub training: bool,
    /// The demo fish's controllers.
    pub controller: ControllerChoice,
}

impl Default for LearningSettings {
    fn default() -> Self {
        Self {
            species: BodySpecies::Fish,
            annealing_steps: 6840,
            training: false,
            controller: ControllerChoice::Learned,
        }
    }
}

impl LearningSettings {
    /// What, when changed, starts the training again.
    pub fn training_key(&self) -> (BodySpecies, u32) {
        (self.species, self.annealing_steps)
    }

    /// The key prefix of these settings in `shoal.set` and the studio's rules.
    pub const PREFIX: &str = "learning.";

    /// Annealing steps per drill.
    pub const ANNEALING_STEPS: NumberSetting<Self, u32> = NumberSetting::<Self, _>::new(
        "learning",
        Range::new("annealing_steps", ANNEALING_STEPS_MIN, ANNEALING_STEPS_MAX),
        field!(annealing_steps),
    )
    .widget(Widget::LOG_SLIDER)
    .rect("learning_steps");
    /// Every numeric setting.
    pub const NUMBERS: [Number<Self>; 1] = [Number::U32(Self::ANNEALING_STEPS)];

    /// The first out-of-range value, its key under `prefix`.
    pub fn validate(&self, prefix: &str) -> Result<(), SettingError> {
        check_all(&Self::NUMBERS, prefix, self)
    }

    pub fn clamp(&mut self) {
        clamp_all(&Self::NUMBERS, self);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_are_checked_and_names_are_stable() {
        let s = LearningSettings::default();
        assert_eq!(s.validate("learning."), Ok(()));
        let bad = LearningSettings {
            annealing_steps: 5,
            ..s.clone()
        };
        assert_eq!(
            bad.validate("learning.").unwrap_err().key,
            "learning.annealing_steps"
        );
        let v: LearningSettings =
            serde_json::from_str(r#"{"species": "shark", "controller": "hand_tuned"}"#).unwrap();
        assert_eq!(v.species, BodySpecies::Shark);
        assert_eq!(v.controller, ControllerChoice::HandTuned);
    }

    #[test]
    fn every_range_refuses_a_value_just_outside_and_clamps_it_to_the_bound() {
        crate::settings::number::check_table(
            &LearningSettings::default(),
            "learning.",
            &LearningSettings::NUMBERS,
            |s| s.validate("learning."),
            LearningSettings::clamp,
        );
    }
}
