//! The settings of the "Physics fish" scene (`Settings::physics`): how many
//! muscle-driven fish and sharks, how they steer, the water current, the selected
//! fish and its hand command, and the debug overlays. Field names are the
//! automation API's names (`shoal.set({physics: {fish_count: 20}})`).

use serde::{Deserialize, Serialize};

use crate::settings::number::{Number, NumberSetting, Unit, Widget, check_all, clamp_all, field};
use crate::settings::range::{Range, SettingError};
use crate::sim::PhysicsBehaviour;
use crate::sim::physics::world::{MAX_PHYSICAL_FISH, MAX_PHYSICAL_SHARKS};
use crate::tr;

/// Most physical fish the slider offers.
pub const PHYSICS_FISH_MAX: u32 = MAX_PHYSICAL_FISH as u32;
/// Most physical sharks.
pub const PHYSICS_SHARKS_MAX: u32 = MAX_PHYSICAL_SHARKS as u32;
/// Strongest water current, m/s (about the default fish's top speed, 0.3 m/s: a
/// fish can barely hold its place against it).
pub const CURRENT_MAX_M_PER_S: f32 = 0.3;
/// Steepest hand-commanded fin pitch, degrees (the bridge's ±0.5 rad ≈ 28.6°).
pub const HAND_PITCH_MAX_DEG: f32 = 28.0;
/// Largest hand-commanded turn, degrees (turns beyond 90° are sequences of smaller
/// ones, `body/turn_mc.rs`).
pub const TURN_MAX_DEG: f32 = 180.0;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PhysicsSettings {
    /// Muscle-driven fish, 1 to [`PHYSICS_FISH_MAX`]. Default 10, as in the
    /// paper's demonstration.
    pub fish_count: u32,
    /// Muscle-driven sharks, 0 to [`PHYSICS_SHARKS_MAX`]. Default 1.
    pub sharks: u32,
    /// How the fish choose where to swim.
    pub behaviour: PhysicsBehaviour,
    /// Speed of the fastest water, m/s, 0 to [`CURRENT_MAX_M_PER_S`]. Default 0.05.
    pub current_m_per_s: f32,
    /// The fish the inspector shows (index: fish first, then sharks), if any.
    pub selected: Option<u32>,
    /// Does the teacher drive the selected fish by hand?
    pub hand_control: bool,
    /// Hand swim speed, fraction of the top speed, 0 to 1. Default 0.6.
    pub hand_speed: f32,
    /// Hand fin pitch, degrees (+ climbs), ±[`HAND_PITCH_MAX_DEG`]. Default 0.
    pub hand_pitch_deg: f32,
    /// The angle the "Turn" button asks for, degrees (+ left), ±[`TURN_MAX_DEG`].
    /// Default 45.
    pub turn_angle_deg: f32,
    /// The camera follows the selected fish.
    pub follow: bool,
    /// Draw the nodes and springs (muscles coloured by contraction).
    pub show_body: bool,
    /// Draw the force arrows: water on each node, wish and velocity.
    pub show_forces: bool,
}

impl Default for PhysicsSettings {
    fn default() -> Self {
        Self {
            fish_count: 10,
            sharks: 1,
            behaviour: PhysicsBehaviour::School,
            current_m_per_s: 0.05,
            selected: None,
            hand_control: false,
            hand_speed: 0.6,
            hand_pitch_deg: 0.0,
            turn_angle_deg: 45.0,
            follow: false,
            show_body: false,
            show_forces: false,
        }
    }
}

impl PhysicsSettings {
    /// All animals (fish and sharks).
    pub fn animal_count(&self) -> u32 {
        self.fish_count + self.sharks
    }

    /// The key prefix of these settings in `shoal.set` and the studio's rules.
    pub const PREFIX: &str = "physics.";

    pub const FISH_COUNT: NumberSetting<Self, u32> = NumberSetting::<Self, _>::new(
        "physics",
        Range::new("fish_count", 1, PHYSICS_FISH_MAX),
        field!(fish_count),
    )
    .widget(Widget::LOG_SLIDER)
    .rect("physics_fish");
    pub const SHARKS: NumberSetting<Self, u32> = NumberSetting::<Self, _>::new(
        "physics",
        Range::new("sharks", 0, PHYSICS_SHARKS_MAX),
        field!(sharks),
    )
    .widget(Widget::Count {
        step: 1,
        typed: false,
    })
    .rect("physics_sharks");
    pub const CURRENT_M_PER_S: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "physics",
        Range::new("current_m_per_s", 0.0, CURRENT_MAX_M_PER_S),
        field!(current_m_per_s),
    )
    .unit(Unit::MetresPerSecond)
    .widget(Widget::slider(2))
    .rect("physics_current");
    pub const HAND_SPEED: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "physics",
        Range::new("hand_speed", 0.0, 1.0),
        field!(hand_speed),
    )
    .widget(Widget::slider(2));
    pub const HAND_PITCH_DEG: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "physics",
        Range::or_else(
            "hand_pitch_deg",
            -HAND_PITCH_MAX_DEG,
            HAND_PITCH_MAX_DEG,
            0.0,
        ),
        field!(hand_pitch_deg),
    )
    .unit(Unit::Degrees)
    .widget(Widget::slider(0))
    .rect("hand_pitch");
    /// Typed in beside the *Turn* button that asks for it.
    pub const TURN_ANGLE_DEG: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "physics",
        Range::or_else("turn_angle_deg", -TURN_MAX_DEG, TURN_MAX_DEG, 0.0),
        field!(turn_angle_deg),
    )
    .unit(Unit::Degrees)
    .widget(Widget::Field {
        drag_speed: 1.0,
        own_help: false,
    })
    .rect("turn_angle");
    /// Every numeric setting (`selected` depends on the counts), in the order
    /// validation reports them.
    pub const NUMBERS: [Number<Self>; 6] = [
        Number::U32(Self::FISH_COUNT),
        Number::U32(Self::SHARKS),
        Number::F32(Self::CURRENT_M_PER_S),
        Number::F32(Self::HAND_SPEED),
        Number::F32(Self::HAND_PITCH_DEG),
        Number::F32(Self::TURN_ANGLE_DEG),
    ];

    /// The first out-of-range value, its key under `prefix`.
    pub fn validate(&self, prefix: &str) -> Result<(), SettingError> {
        check_all(&Self::NUMBERS, prefix, self)?;
        if let Some(selected) = self.selected
            && selected >= self.animal_count()
        {
            return Err(SettingError {
                key: format!("{prefix}selected"),
                reason: tr!(
                    "setting-error-selected-animal",
                    selected = selected,
                    count = self.animal_count(),
                    last = self.animal_count() - 1
                ),
            });
        }
        // Steering by hand and the following camera act on the selected fish:
        // without one they would be dropped, so they are refused instead.
        if self.selected.is_none() {
            for (on, key) in [(self.hand_control, "hand_control"), (self.follow, "follow")] {
                if on {
                    return Err(SettingError {
                        key: format!("{prefix}{key}"),
                        reason: tr!("setting-error-needs-selected-fish"),
                    });
                }
            }
        }
        Ok(())
    }

    /// Brings every value into range.
    pub fn clamp(&mut self) {
        clamp_all(&Self::NUMBERS, self);
        if self.selected.is_some_and(|s| s >= self.animal_count()) {
            self.selected = None;
        }
        if self.selected.is_none() {
            self.hand_control = false;
            self.follow = false;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_each_range_is_checked() {
        let ok = PhysicsSettings::default();
        assert_eq!(ok.validate("physics."), Ok(()));
        type Breaker = fn(&mut PhysicsSettings);
        let cases: [(&str, Breaker); 7] = [
            ("physics.fish_count", |s| s.fish_count = 0),
            ("physics.fish_count", |s| {
                s.fish_count = PHYSICS_FISH_MAX + 1
            }),
            ("physics.sharks", |s| s.sharks = 4),
            ("physics.current_m_per_s", |s| s.current_m_per_s = f32::NAN),
            ("physics.hand_speed", |s| s.hand_speed = 1.5),
            ("physics.turn_angle_deg", |s| s.turn_angle_deg = -200.0),
            ("physics.selected", |s| s.selected = Some(11)),
        ];
        for (key, break_it) in cases {
            let mut s = ok.clone();
            break_it(&mut s);
            let SettingError { key: got, reason } = s.validate("physics.").unwrap_err();
            assert_eq!(got, key, "{reason}");
            assert!(reason.contains("out of range"), "{reason}");
            s.clamp();
            assert_eq!(s.validate("physics."), Ok(()), "clamp fixes {key}");
        }
    }

    #[test]
    fn without_a_selection_there_is_no_hand_control_or_follow_camera() {
        let mut s = PhysicsSettings {
            selected: Some(3),
            hand_control: true,
            follow: true,
            ..PhysicsSettings::default()
        };
        s.fish_count = 2;
        s.sharks = 0;
        s.clamp();
        assert_eq!(s.selected, None);
        assert!(!s.hand_control && !s.follow);
    }

    #[test]
    fn every_range_refuses_a_value_just_outside_and_clamps_it_to_the_bound() {
        crate::settings::number::check_table(
            &PhysicsSettings::default(),
            "physics.",
            &PhysicsSettings::NUMBERS,
            |s| s.validate("physics."),
            PhysicsSettings::clamp,
        );
    }
}
