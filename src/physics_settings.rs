//! The settings of the "Physics fish" scene (`Settings::physics`): how many
//! muscle-driven fish and sharks, how they steer, the water current, the selected
//! fish and its hand command, and the debug overlays. Field names are the
//! automation API's names (`shoal.set({physics: {fish_count: 20}})`).

use serde::{Deserialize, Serialize};

use crate::sim::PhysicsBehaviour;
use crate::sim::physics::world::{MAX_PHYSICAL_FISH, MAX_PHYSICAL_SHARKS};

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

    /// The first out-of-range value as (key under `prefix`, reason).
    pub fn validate(&self, prefix: &str) -> Result<(), (String, String)> {
        let out = |key: &str, value: String, lo: String, hi: String| {
            Err((
                format!("{prefix}{key}"),
                format!("{value} is out of range: choose from {lo} to {hi}"),
            ))
        };
        let range = |key: &str, value: f32, lo: f32, hi: f32| {
            if value.is_finite() && (lo..=hi).contains(&value) {
                Ok(())
            } else {
                out(key, value.to_string(), lo.to_string(), hi.to_string())
            }
        };
        if !(1..=PHYSICS_FISH_MAX).contains(&self.fish_count) {
            return out(
                "fish_count",
                self.fish_count.to_string(),
                "1".into(),
                PHYSICS_FISH_MAX.to_string(),
            );
        }
        if self.sharks > PHYSICS_SHARKS_MAX {
            return out(
                "sharks",
                self.sharks.to_string(),
                "0".into(),
                PHYSICS_SHARKS_MAX.to_string(),
            );
        }
        range(
            "current_m_per_s",
            self.current_m_per_s,
            0.0,
            CURRENT_MAX_M_PER_S,
        )?;
        range("hand_speed", self.hand_speed, 0.0, 1.0)?;
        range(
            "hand_pitch_deg",
            self.hand_pitch_deg,
            -HAND_PITCH_MAX_DEG,
            HAND_PITCH_MAX_DEG,
        )?;
        range(
            "turn_angle_deg",
            self.turn_angle_deg,
            -TURN_MAX_DEG,
            TURN_MAX_DEG,
        )?;
        if let Some(selected) = self.selected
            && selected >= self.animal_count()
        {
            return Err((
                format!("{prefix}selected"),
                format!(
                    "{selected} is out of range: there are {} animals (0 to {}), or null for none",
                    self.animal_count(),
                    self.animal_count() - 1
                ),
            ));
        }
        Ok(())
    }

    /// Brings every value into range.
    pub fn clamp(&mut self) {
        let clamp = |v: &mut f32, lo: f32, hi: f32, default: f32| {
            *v = if v.is_finite() {
                v.clamp(lo, hi)
            } else {
                default
            };
        };
        self.fish_count = self.fish_count.clamp(1, PHYSICS_FISH_MAX);
        self.sharks = self.sharks.min(PHYSICS_SHARKS_MAX);
        clamp(&mut self.current_m_per_s, 0.0, CURRENT_MAX_M_PER_S, 0.0);
        clamp(&mut self.hand_speed, 0.0, 1.0, 0.0);
        clamp(
            &mut self.hand_pitch_deg,
            -HAND_PITCH_MAX_DEG,
            HAND_PITCH_MAX_DEG,
            0.0,
        );
        clamp(&mut self.turn_angle_deg, -TURN_MAX_DEG, TURN_MAX_DEG, 0.0);
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
            let (got, reason) = s.validate("physics.").unwrap_err();
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
}
