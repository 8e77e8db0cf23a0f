//! The settings of the "Reef" scene (`Settings::reef`): fish with minds (Tu &
//! Terzopoulos §5–7). Which demo, which body carries the minds, the water, the
//! selected fish and the overlays. Field names are the automation API's names
//! (`shoal.set({reef: {demo: "courtship"}})`).

use serde::{Deserialize, Serialize};

use crate::i18n::ts;
use crate::settings::number::{Number, NumberSetting, Unit, check_all, clamp_all, field};
use crate::settings::range::{Range, SettingError};
use crate::sim::reef::demos::ReefScene;
use crate::sim::reef::mind::FishKind;
use crate::sim::reef::mind::habits::{KindTraits, MindTraits};
use crate::sim::reef::world::{MAX_FOOD, ReefBodyKind, ReefConfig};

/// Most prey fish the slider offers: the Reef demo then holds
/// `MAX_REEF_ANIMALS` (200) animals.
pub const REEF_PREY_MAX: u32 = 192;
/// Most plankton particles the slider offers.
pub const REEF_FOOD_MAX: u32 = MAX_FOOD as u32;
/// Water visibility V_r range, metres.
pub const VISIBILITY_MIN_M: f32 = 1.0;
pub const VISIBILITY_MAX_M: f32 = 12.0;
/// Strongest current, m/s (as in the physics scene).
pub const REEF_CURRENT_MAX_M_PER_S: f32 = 0.3;

/// A colour overlay of the water.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ReefOverlay {
    #[default]
    None,
    /// Brightness: bright near the sunlit surface, dark deep and in the shade.
    Light,
    /// Temperature: warm near the vent, cold deep at the far end.
    Temperature,
}

impl ReefOverlay {
    pub const ALL: [Self; 3] = [Self::None, Self::Light, Self::Temperature];

    /// Its name in rectangle names (`reef_overlay_light`), the same in every
    /// language.
    pub fn name(self) -> &'static str {
        match self {
            Self::None => "none",
            Self::Light => "light",
            Self::Temperature => "temperature",
        }
    }

    pub fn label(self) -> &'static str {
        match self {
            Self::None => ts("setting-reef-overlay-none"),
            Self::Light => ts("setting-reef-overlay-light"),
            Self::Temperature => ts("setting-reef-overlay-temperature"),
        }
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ReefSettings {
    /// Which demo scene.
    pub demo: ReefScene,
    /// The muscle-driven body (default) or the light point-mass body.
    pub body: ReefBodyKind,
    /// Prey fish in the demos with a school (`None`: the demo's own number),
    /// 0 to [`REEF_PREY_MAX`].
    pub prey_count: Option<u32>,
    /// Plankton kept in the water (`None`: the demo's own number), 0 to
    /// [`REEF_FOOD_MAX`].
    pub food_count: Option<u32>,
    /// How far fish see, metres, [`VISIBILITY_MIN_M`] to [`VISIBILITY_MAX_M`].
    /// Default 6.
    pub visibility_m: f32,
    /// Speed of the fastest water, m/s. Default 0.03.
    pub current_m_per_s: f32,
    /// The fish the inspector shows, if any.
    pub selected: Option<u32>,
    /// The camera follows the selected fish.
    pub follow: bool,
    /// Draw the selected fish's view volume and focus line.
    pub show_vision: bool,
    /// Colour the water by light or temperature.
    pub overlay: ReefOverlay,
    /// Write each animal's name ("shark 10", "fish 5") over it, as the event
    /// log and the inspector call it.
    pub name_tags: bool,
    /// The teacher's changes to the minds of predators, prey and pacifists
    /// (`null` values keep the demo's own); they apply at once.
    pub traits: KindTraits,
}

impl Default for ReefSettings {
    fn default() -> Self {
        Self {
            demo: ReefScene::Reef,
            body: ReefBodyKind::Physical,
            prey_count: None,
            food_count: None,
            visibility_m: 6.0,
            current_m_per_s: 0.03,
            selected: None,
            follow: false,
            show_vision: true,
            name_tags: false,
            overlay: ReefOverlay::None,
            traits: KindTraits::default(),
        }
    }
}

impl ReefSettings {
    /// The world these settings build from `seed`.
    pub fn config(&self, seed: u64) -> ReefConfig {
        ReefConfig {
            seed,
            scene: self.demo,
            body: self.body,
            visibility_m: self.visibility_m,
            current_m_per_s: self.current_m_per_s,
            food_count: self.food_count.map(|n| n as usize),
            prey_count: self.prey_count.map(|n| n as usize),
            traits: self.traits,
        }
    }

    /// Chooses `demo` as its button in the panel does: the demo's own fish
    /// and food counts, and no fish selected, except in *Feeding*, which is
    /// about bites too small to see from across the tank and so opens
    /// following its first fish.
    pub fn choose_demo(&mut self, demo: ReefScene) {
        if self.demo == demo {
            return;
        }
        self.demo = demo;
        self.prey_count = None;
        self.food_count = None;
        let feeding = demo == ReefScene::Feeding;
        self.selected = feeding.then_some(0);
        self.follow = feeding;
    }

    /// Animals in the reef these settings build.
    pub fn animal_count(&self) -> usize {
        let prey = self
            .prey_count
            .map_or(self.demo.default_prey_count(), |n| n as usize);
        self.demo.animal_count(prey)
    }

    /// What, when changed, needs a new reef (the others apply live).
    pub fn rebuild_key(&self) -> (ReefScene, ReefBodyKind, Option<u32>, Option<u32>) {
        (self.demo, self.body, self.prey_count, self.food_count)
    }

    /// The key prefix of these settings in `shoal.set` and the studio's rules.
    pub const PREFIX: &str = "reef.";

    /// Unset, the demo's own number.
    pub const PREY_COUNT: NumberSetting<Self, u32> = NumberSetting::<Self, _>::new(
        "reef",
        Range::new("prey_count", 0, REEF_PREY_MAX),
        field!(prey_count, |r| r.demo.default_prey_count() as u32),
    )
    .rect("reef_prey");
    /// Unset, the demo's own number.
    pub const FOOD_COUNT: NumberSetting<Self, u32> = NumberSetting::<Self, _>::new(
        "reef",
        Range::new("food_count", 0, REEF_FOOD_MAX),
        field!(food_count, |r| r.demo.default_food_count() as u32),
    )
    .rect("reef_food");
    pub const VISIBILITY_M: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "reef",
        Range::or_else("visibility_m", VISIBILITY_MIN_M, VISIBILITY_MAX_M, 6.0),
        field!(visibility_m),
    )
    .unit(Unit::Metres)
    .rect("reef_visibility");
    pub const CURRENT_M_PER_S: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "reef",
        Range::or_else("current_m_per_s", 0.0, REEF_CURRENT_MAX_M_PER_S, 0.03),
        field!(current_m_per_s),
    )
    .unit(Unit::MetresPerSecond)
    .rect("reef_current");
    /// Every numeric setting (each kind's traits have their own table,
    /// [`MindTraits::NUMBERS`], under [`MindTraits::prefix`]; `selected`
    /// depends on the demo and the counts), in the order validation reports them.
    pub const NUMBERS: [Number<Self>; 4] = [
        Number::U32(Self::PREY_COUNT),
        Number::U32(Self::FOOD_COUNT),
        Number::F32(Self::VISIBILITY_M),
        Number::F32(Self::CURRENT_M_PER_S),
    ];

    /// The first out-of-range value, its key under `prefix`.
    pub fn validate(&self, prefix: &str) -> Result<(), SettingError> {
        check_all(&Self::NUMBERS, prefix, self)?;
        for kind in FishKind::ALL {
            let kind_prefix = MindTraits::prefix(prefix, kind);
            check_all(&MindTraits::NUMBERS, &kind_prefix, self.traits.of(kind))?;
        }
        let animals = self.animal_count();
        if let Some(i) = self.selected
            && i as usize >= animals
        {
            return Err(SettingError::out_of_range(
                format!("{prefix}selected"),
                i,
                0,
                animals.saturating_sub(1),
            ));
        }
        Ok(())
    }

    /// Brings every value into range.
    pub fn clamp(&mut self) {
        clamp_all(&Self::NUMBERS, self);
        for kind in FishKind::ALL {
            clamp_all(&MindTraits::NUMBERS, self.traits.of_mut(kind));
        }
        let animals = self.animal_count();
        self.selected = self.selected.filter(|&i| (i as usize) < animals);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_out_of_range_values_are_named() {
        let s = ReefSettings::default();
        assert_eq!(s.validate("reef."), Ok(()));
        let bad = ReefSettings {
            visibility_m: 40.0,
            ..s.clone()
        };
        let SettingError { key, reason } = bad.validate("reef.").unwrap_err();
        assert_eq!(key, "reef.visibility_m");
        assert!(reason.contains("choose from 1 to 12"), "{reason}");
        let bad = ReefSettings {
            prey_count: Some(1000),
            ..s.clone()
        };
        assert_eq!(bad.validate("reef.").unwrap_err().key, "reef.prey_count");
        let mut nan = ReefSettings {
            current_m_per_s: f32::NAN,
            prey_count: Some(999),
            ..s
        };
        nan.clamp();
        assert_eq!(nan.current_m_per_s, 0.03);
        assert_eq!(nan.prey_count, Some(REEF_PREY_MAX));
        assert_eq!(nan.validate("reef."), Ok(()));
    }

    #[test]
    fn traits_are_checked_named_and_clamped() {
        let mut s = ReefSettings::default();
        s.traits.predator.digestion_rate_per_unit = Some(0.005);
        s.traits.pacifist.libido_rate_per_unit = Some(0.01);
        assert_eq!(s.validate("reef."), Ok(()));
        let json = serde_json::to_string(&s).unwrap();
        assert_eq!(serde_json::from_str::<ReefSettings>(&json).unwrap(), s);
        s.traits.prey.fear_threshold = Some(0.9);
        let SettingError { key, reason } = s.validate("reef.").unwrap_err();
        assert_eq!(key, "reef.traits.prey.fear_threshold");
        assert!(reason.contains("choose from 0.1 to 0.5"), "{reason}");
        s.traits.prey.urge_threshold = Some(f32::NAN);
        s.clamp();
        assert_eq!(s.traits.prey.fear_threshold, Some(0.5));
        assert_eq!(s.traits.prey.urge_threshold, None);
        assert_eq!(s.validate("reef."), Ok(()));
        assert!(
            serde_json::from_str::<ReefSettings>(r#"{"traits": {"prey": {"hunger": 1}}}"#).is_err()
        );
    }

    #[test]
    fn links_made_before_the_one_clock_still_open() {
        // The rates were called `…_per_step` before they were per paper time unit.
        let s: ReefSettings = serde_json::from_str(
            r#"{"traits": {"predator": {"digestion_rate_per_step": 0.005},
                           "pacifist": {"libido_rate_per_step": 0.01}}}"#,
        )
        .expect("old names accepted");
        assert_eq!(s.traits.predator.digestion_rate_per_unit, Some(0.005));
        assert_eq!(s.traits.pacifist.libido_rate_per_unit, Some(0.01));
    }

    #[test]
    fn the_demo_names_round_trip_through_json() {
        for demo in ReefScene::ALL {
            let s = ReefSettings {
                demo,
                ..ReefSettings::default()
            };
            let json = serde_json::to_string(&s).unwrap();
            assert_eq!(serde_json::from_str::<ReefSettings>(&json).unwrap(), s);
        }
        let v: ReefSettings =
            serde_json::from_str(r#"{"demo": "school_meets_obstacle", "body": "point_mass"}"#)
                .unwrap();
        assert_eq!(v.demo, ReefScene::SchoolMeetsObstacle);
        assert_eq!(v.body, ReefBodyKind::PointMass);
    }

    #[test]
    fn every_range_refuses_a_value_just_outside_and_clamps_it_to_the_bound() {
        crate::settings::number::check_table(
            &ReefSettings::default(),
            "reef.",
            &ReefSettings::NUMBERS,
            |s| s.validate("reef."),
            ReefSettings::clamp,
        );
    }
}
