//! What a teacher sets for one tank of the boid scene: the five SIMBA force weights on
//! the papers' 0–100 scale, the control mode, what the fish perceive, and how many
//! animals of each species swim in it (Lim & Tan; docs/boids.md).
//!
//! A preset ("Individual", "Group", the Monte Carlo paper partition) sets the five
//! weights (the paper partition also the Monte Carlo mode) and nothing else: senses,
//! body and wander are visible controls of their own, the same whatever the preset,
//! so a difference between an *Individual* and a *Group* tank is caused by the
//! weights alone. Moving a weight by hand makes the preset "Custom", and setting the
//! weights back to a preset's values makes it that preset again, so the label always
//! tells the truth.

use serde::{Deserialize, Serialize};

use crate::i18n::ts;
use crate::settings::number::{Number, NumberSetting, Unit, Widget, check_all, clamp_all, field};
use crate::settings::range::{Range, SettingError};
use crate::sim::boids::control_mode::{self, ControlMode};
use crate::sim::boids::shark::MAX_SHARKS;
use crate::sim::boids::stingray::MAX_STINGRAYS;
use crate::sim::{BoidParams, Tank};
use crate::tr;

/// Largest fish count a teacher can ask for (per tank).
pub const FISH_COUNT_MAX: u32 = 20_000;
/// Largest number of sharks per tank.
pub const SHARKS_MAX: u32 = MAX_SHARKS as u32;
/// Largest number of stingrays per tank.
pub const STINGRAYS_MAX: u32 = MAX_STINGRAYS as u32;
/// Force weights run from 0 to this, as in the papers' Table 1.
pub const WEIGHT_MAX: f32 = 100.0;
/// Named sets of weights and perception.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Preset {
    /// Table 1, solitary animals: high separation and containment, no cohesion.
    #[default]
    Individual,
    /// Table 1, schooling animals: balanced forces, strong avoidance.
    Group,
    /// The Monte Carlo control mode with the papers' published partition of 3.2.
    MonteCarloPaper,
    /// Anything else: the teacher moved a slider.
    Custom,
}

impl Preset {
    pub const ALL: [Self; 4] = [
        Self::Individual,
        Self::Group,
        Self::MonteCarloPaper,
        Self::Custom,
    ];

    /// The name on the radio button.
    pub fn label(self) -> &'static str {
        match self {
            Self::Individual => ts("setting-preset-individual"),
            Self::Group => ts("setting-preset-group"),
            Self::MonteCarloPaper => ts("setting-preset-monte-carlo-paper"),
            Self::Custom => ts("setting-preset-custom"),
        }
    }

    /// Hover help a 12-year-old understands.
    pub fn help(self) -> &'static str {
        match self {
            Self::Individual => ts("setting-preset-individual.help"),
            Self::Group => ts("setting-preset-group.help"),
            Self::MonteCarloPaper => ts("setting-preset-monte-carlo-paper.help"),
            Self::Custom => ts("setting-preset-custom.help"),
        }
    }

    /// The weights this preset sets, and the mode it implies (only the paper's
    /// Monte Carlo partition implies one); `None` for Custom.
    pub fn weights_and_mode(self) -> Option<([f32; 5], Option<ControlMode>)> {
        match self {
            Self::Individual => Some((control_mode::INDIVIDUAL_WEIGHTS, None)),
            Self::Group => Some((control_mode::GROUP_WEIGHTS, None)),
            // The published partition as shares of 100 (0.6/3.2 → 18.75 …), so the
            // lottery's chances are the paper's and the sliders read as percentages.
            Self::MonteCarloPaper => Some((
                control_mode::MONTE_CARLO_PAPER_WEIGHTS.map(|w| w * 100.0 / 3.2),
                Some(ControlMode::MonteCarlo),
            )),
            Self::Custom => None,
        }
    }
}

/// One tank's boid settings. Field names are the automation API's and share links'
/// names; units are in the names.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TankSettings {
    pub preset: Preset,
    pub mode: ControlMode,
    /// Stay inside the tank, 0–100.
    pub containment: f32,
    /// Swim the same way as the neighbours, 0–100.
    pub alignment: f32,
    /// Move towards the neighbours' centre, 0–100.
    pub cohesion: f32,
    /// Keep space from the neighbours, 0–100.
    pub separation: f32,
    /// Swerve around rocks, pillars, ledges and stingrays, 0–100.
    pub avoidance: f32,
    pub vision_distance_m: f32,
    pub vision_angle_deg: f32,
    pub max_speed_m_per_s: f32,
    pub max_force_m_per_s2: f32,
    /// Neighbours closer than this push the fish away (separation), metres.
    pub personal_space_m: f32,
    /// Urge to roam on its own (a wander steering force), 0–100.
    pub wander: f32,
    /// Within this distance a neighbour's heading is read in full, metres
    /// (`Perception::clear_sight_m`). Links made before it was a control lack
    /// it and get the value the fish had then.
    #[serde(default = "default_clear_sight_m")]
    pub clear_sight_m: f32,
    /// Pull towards the distant fish seen, as a percentage of the pull towards
    /// the close neighbours (`Perception::far_pull` × 100).
    #[serde(default = "default_distant_pull")]
    pub distant_pull: f32,
    /// The speed a fish never drops below, m/s.
    #[serde(default = "default_min_speed_m_per_s")]
    pub min_speed_m_per_s: f32,
    pub fish_count: u32,
    pub sharks: u32,
    pub stingrays: u32,
    /// `None`: the rocks, pillars and ledges the seed places; a list: exactly these
    /// (after a teacher added, moved or removed one).
    pub obstacles: Option<Vec<crate::sim::Obstacle>>,
    /// The fish whose attention the schooling lab shows (its index, below
    /// `fish_count`), if any. Each tank has its own. Links made before it
    /// existed lack it.
    #[serde(default)]
    pub selected: Option<u32>,
}

impl TankSettings {
    /// A tank with `preset`'s weights, the boid layer's default senses, body and
    /// wander ([`BoidParams::group`], the same for every preset), 200 fish, no
    /// predators.
    pub fn with_preset(preset: Preset) -> Self {
        let defaults = BoidParams::group();
        let p = defaults.perception;
        let mut tank = Self {
            preset,
            mode: defaults.mode,
            containment: 0.0,
            alignment: 0.0,
            cohesion: 0.0,
            separation: 0.0,
            avoidance: 0.0,
            vision_distance_m: p.vision_distance_m,
            vision_angle_deg: p.vision_angle_rad.to_degrees().round(),
            max_speed_m_per_s: p.max_speed_m_per_s,
            max_force_m_per_s2: p.max_force_m_per_s2,
            personal_space_m: p.separation_distance_m,
            wander: defaults.wander_weight,
            clear_sight_m: p.clear_sight_m,
            distant_pull: p.far_pull * 100.0,
            min_speed_m_per_s: p.min_speed_m_per_s,
            fish_count: 200,
            sharks: 0,
            stingrays: 0,
            obstacles: None,
            selected: None,
        };
        tank.load_preset(preset);
        tank
    }

    /// The five weights in [`control_mode::Force::ALL`] order.
    pub fn weights(&self) -> [f32; 5] {
        Self::WEIGHTS.map(|w| w.value(self))
    }

    fn set_weights(&mut self, weights: [f32; 5]) {
        for (w, value) in Self::WEIGHTS.iter().zip(weights) {
            w.set(self, value);
        }
    }

    /// What the simulation runs with.
    pub fn boid_params(&self) -> BoidParams {
        let mut params = BoidParams::group();
        params.weights = self.weights();
        params.mode = self.mode;
        params.perception.vision_distance_m = self.vision_distance_m;
        params.perception.vision_angle_rad = self.vision_angle_deg.to_radians();
        params.perception.max_speed_m_per_s = self.max_speed_m_per_s;
        params.perception.max_force_m_per_s2 = self.max_force_m_per_s2;
        params.perception.separation_distance_m = self.personal_space_m;
        params.wander_weight = self.wander;
        params.perception.clear_sight_m = self.clear_sight_m;
        params.perception.far_pull = self.distant_pull / 100.0;
        params.perception.min_speed_m_per_s = self.min_speed_m_per_s;
        params
    }

    /// Sets the weights (and, for the paper partition, the mode) of `preset`;
    /// nothing else. Custom changes nothing.
    pub fn load_preset(&mut self, preset: Preset) {
        self.preset = preset;
        let Some((weights, mode)) = preset.weights_and_mode() else {
            return;
        };
        self.set_weights(weights);
        if let Some(mode) = mode {
            self.mode = mode;
        }
    }

    /// The preset whose weights (and, for the paper partition, mode) these are,
    /// or Custom.
    pub fn matching_preset(&self) -> Preset {
        Preset::ALL
            .into_iter()
            .find(|&preset| {
                preset.weights_and_mode().is_some_and(|(weights, mode)| {
                    // Only the paper partition includes a mode; Table 1's presets
                    // work in any mode.
                    weights == self.weights() && mode.is_none_or(|mode| mode == self.mode)
                })
            })
            .unwrap_or(Preset::Custom)
    }

    /// Makes the preset label true after an edit: a newly chosen preset loads its
    /// values; otherwise the label follows the values.
    pub fn settle(&mut self, before: &Self) {
        if self.preset != before.preset && self.preset != Preset::Custom {
            self.load_preset(self.preset);
        } else {
            self.preset = self.matching_preset();
        }
    }

    /// The five urge weights in [`control_mode::Force::ALL`] order, 0 to
    /// [`WEIGHT_MAX`]: the sliders a preset sets.
    pub const WEIGHTS: [NumberSetting<Self, f32>; 5] = [
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("containment", 0.0, WEIGHT_MAX),
            field!(containment),
        )
        .widget(WHOLE)
        .rect("weight_containment"),
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("alignment", 0.0, WEIGHT_MAX),
            field!(alignment),
        )
        .widget(WHOLE)
        .rect("weight_alignment"),
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("cohesion", 0.0, WEIGHT_MAX),
            field!(cohesion),
        )
        .widget(WHOLE)
        .rect("weight_cohesion"),
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("separation", 0.0, WEIGHT_MAX),
            field!(separation),
        )
        .widget(WHOLE)
        .rect("weight_separation"),
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("avoidance", 0.0, WEIGHT_MAX),
            field!(avoidance),
        )
        .widget(WHOLE)
        .rect("weight_avoidance"),
    ];

    /// The senses, the body and the urge to roam: the same whatever the preset.
    pub const SENSES: [NumberSetting<Self, f32>; 9] = [
        // From under two body lengths to the tank's width.
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("vision_distance_m", 0.5, 12.0),
            field!(vision_distance_m),
        )
        .unit(Unit::Metres)
        .widget(TENTHS),
        // 360: no blind spot.
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("vision_angle_deg", 0.0, 360.0),
            field!(vision_angle_deg),
        )
        .unit(Unit::Degrees)
        .widget(TENTHS),
        // From a crawl (a third of a body length per second) to a sprint (about
        // ten body lengths per second).
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("max_speed_m_per_s", 0.1, 3.0),
            field!(max_speed_m_per_s),
        )
        .unit(Unit::MetresPerSecond)
        .widget(TENTHS),
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("max_force_m_per_s2", 0.1, 10.0),
            field!(max_force_m_per_s2),
        )
        .unit(Unit::MetresPerSecondSquared)
        .widget(TENTHS),
        // From a third of a body length (packed) to ten body lengths (a loner
        // that keeps everybody away).
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("personal_space_m", 0.1, 3.0),
            field!(personal_space_m),
        )
        .unit(Unit::Metres)
        .widget(TENTHS),
        // On the weights' scale.
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("wander", 0.0, WEIGHT_MAX),
            field!(wander),
        )
        .widget(TENTHS),
        // From reading no heading at all to reading every fish seen across the
        // tank's width in full.
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("clear_sight_m", 0.0, 12.0),
            field!(clear_sight_m),
        )
        .unit(Unit::Metres)
        .widget(TENTHS),
        // From none (only the close neighbours attract) to as strong as the
        // close neighbours' pull.
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("distant_pull", 0.0, WEIGHT_MAX),
            field!(distant_pull),
        )
        .widget(WHOLE),
        // From drifting to a stop to faster than a crawl.
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("min_speed_m_per_s", 0.0, 1.0),
            field!(min_speed_m_per_s),
        )
        .unit(Unit::MetresPerSecond)
        .widget(Widget::slider(2)),
    ];

    /// The animals in the tank: fish, sharks, stingrays.
    pub const COUNTS: [NumberSetting<Self, u32>; 3] = [
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("fish_count", 0, FISH_COUNT_MAX),
            field!(fish_count),
        )
        .widget(Widget::Count {
            step: 10,
            typed: true,
        })
        .rect("fish"),
        NumberSetting::<Self, _>::new("tank", Range::new("sharks", 0, SHARKS_MAX), field!(sharks))
            .widget(ONE_AT_A_TIME),
        NumberSetting::<Self, _>::new(
            "tank",
            Range::new("stingrays", 0, STINGRAYS_MAX),
            field!(stingrays),
        )
        .widget(ONE_AT_A_TIME),
    ];

    /// The aquarium scene's one control: the fish count of [`Self::COUNTS`] as a
    /// slider, in the aquarium's words (`setting-aquarium-fish-count`; not in
    /// [`Self::NUMBERS`]: the same setting).
    pub const AQUARIUM_FISH_COUNT: NumberSetting<Self, u32> = NumberSetting {
        section: "aquarium",
        widget: Widget::LOG_SLIDER,
        rect: "fish_count",
        ..Self::COUNTS[0]
    };

    /// Every numeric setting, in the order validation reports them.
    pub const NUMBERS: [Number<Self>; 17] = [
        Number::F32(Self::WEIGHTS[0]),
        Number::F32(Self::WEIGHTS[1]),
        Number::F32(Self::WEIGHTS[2]),
        Number::F32(Self::WEIGHTS[3]),
        Number::F32(Self::WEIGHTS[4]),
        Number::F32(Self::SENSES[0]),
        Number::F32(Self::SENSES[1]),
        Number::F32(Self::SENSES[2]),
        Number::F32(Self::SENSES[3]),
        Number::F32(Self::SENSES[4]),
        Number::F32(Self::SENSES[5]),
        Number::F32(Self::SENSES[6]),
        Number::F32(Self::SENSES[7]),
        Number::F32(Self::SENSES[8]),
        Number::U32(Self::COUNTS[0]),
        Number::U32(Self::COUNTS[1]),
        Number::U32(Self::COUNTS[2]),
    ];

    /// Checks every range; `prefix` names the tank in messages ("left.").
    pub fn validate(&self, prefix: &str, tank: &Tank) -> Result<(), SettingError> {
        check_all(&Self::NUMBERS, prefix, self)?;
        if let Some(selected) = self.selected
            && selected >= self.fish_count
        {
            return Err(SettingError {
                key: format!("{prefix}selected"),
                reason: tr!(
                    "setting-error-selected-fish",
                    selected = selected,
                    count = self.fish_count,
                    last = i64::from(self.fish_count) - 1
                ),
            });
        }
        if let Some(obstacles) = &self.obstacles {
            if obstacles.len() > MAX_OBSTACLES {
                return Err(SettingError {
                    key: format!("{prefix}obstacles"),
                    reason: tr!(
                        "setting-error-too-many-obstacles",
                        count = obstacles.len(),
                        max = MAX_OBSTACLES
                    ),
                });
            }
            for (i, obstacle) in obstacles.iter().enumerate() {
                obstacle.validate(tank).map_err(|reason| SettingError {
                    key: format!("{prefix}obstacles[{i}]"),
                    reason: reason.to_string(),
                })?;
            }
        }
        Ok(())
    }

    /// Brings every value into its range (for paths that cannot refuse, such as the
    /// UI's own widgets). Invalid obstacles are dropped.
    pub fn clamp(&mut self, tank: &Tank) {
        clamp_all(&Self::NUMBERS, self);
        // Fewer fish than the selected one's number: let it go.
        self.selected = self.selected.filter(|&i| i < self.fish_count);
        if let Some(obstacles) = &mut self.obstacles {
            obstacles.retain(|o| o.validate(tank).is_ok());
            obstacles.truncate(MAX_OBSTACLES);
        }
    }
}

fn default_clear_sight_m() -> f32 {
    BoidParams::group().perception.clear_sight_m
}

fn default_distant_pull() -> f32 {
    BoidParams::group().perception.far_pull * 100.0
}

fn default_min_speed_m_per_s() -> f32 {
    BoidParams::group().perception.min_speed_m_per_s
}

/// Most obstacles a tank may hold: plenty for a lesson, bounded for share links.
pub const MAX_OBSTACLES: usize = 24;

/// The urge weights' slider: whole numbers on the papers' 0–100 scale.
const WHOLE: Widget = Widget::slider(0);

/// The senses' (body's, wander's) slider: to a tenth.
const TENTHS: Widget = Widget::slider(1);

/// Sharks and stingrays come one at a time.
const ONE_AT_A_TIME: Widget = Widget::Count {
    step: 1,
    typed: true,
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_carry_table_1_and_are_recognised() {
        let individual = TankSettings::with_preset(Preset::Individual);
        assert_eq!(individual.weights(), control_mode::INDIVIDUAL_WEIGHTS);
        assert_eq!(individual.matching_preset(), Preset::Individual);
        let group = TankSettings::with_preset(Preset::Group);
        assert_eq!(group.weights(), control_mode::GROUP_WEIGHTS);
        assert_eq!(group.matching_preset(), Preset::Group);
        let paper = TankSettings::with_preset(Preset::MonteCarloPaper);
        assert_eq!(paper.mode, ControlMode::MonteCarlo);
        let sum: f32 = paper.weights().iter().sum();
        assert!((sum - 100.0).abs() < 1e-3, "{sum}");
        assert_eq!(paper.matching_preset(), Preset::MonteCarloPaper);
    }

    #[test]
    fn moving_a_slider_makes_custom_and_moving_it_back_restores_the_preset() {
        let before = TankSettings::with_preset(Preset::Group);
        let mut after = before.clone();
        after.cohesion = 80.0;
        after.settle(&before);
        assert_eq!(after.preset, Preset::Custom);
        let mut back = after.clone();
        back.cohesion = control_mode::GROUP_WEIGHTS[2];
        back.settle(&after);
        assert_eq!(back.preset, Preset::Group);
    }

    #[test]
    fn a_preset_sets_only_the_weights() {
        let mut tank = TankSettings::with_preset(Preset::Individual);
        tank.personal_space_m = 1.5;
        tank.wander = 40.0;
        tank.vision_distance_m = 3.0;
        let before = tank.clone();
        tank.preset = Preset::Group;
        tank.settle(&before);
        assert_eq!(tank.weights(), control_mode::GROUP_WEIGHTS);
        assert_eq!(tank.personal_space_m, 1.5);
        assert_eq!(tank.wander, 40.0);
        assert_eq!(tank.vision_distance_m, 3.0);
        assert_eq!(tank.preset, Preset::Group, "the label names the weights");
    }

    #[test]
    fn choosing_a_preset_loads_its_values() {
        let before = TankSettings::with_preset(Preset::Individual);
        let mut after = before.clone();
        after.preset = Preset::Group;
        after.settle(&before);
        assert_eq!(after.weights(), control_mode::GROUP_WEIGHTS);
        assert_eq!(after.preset, Preset::Group);
    }

    #[test]
    fn the_mode_alone_does_not_change_the_table_1_presets() {
        let before = TankSettings::with_preset(Preset::Group);
        let mut after = before.clone();
        after.mode = ControlMode::Classic;
        after.settle(&before);
        assert_eq!(after.preset, Preset::Group);
        let paper = TankSettings::with_preset(Preset::MonteCarloPaper);
        let mut blended = paper.clone();
        blended.mode = ControlMode::Blended;
        blended.settle(&paper);
        assert_eq!(
            blended.preset,
            Preset::Custom,
            "the paper preset is a lottery"
        );
    }

    #[test]
    fn validation_names_the_setting() {
        let tank = Tank::default();
        let mut settings = TankSettings::with_preset(Preset::Group);
        settings.separation = 101.0;
        let SettingError { key, reason } = settings.validate("left.", &tank).unwrap_err();
        assert_eq!(key, "left.separation");
        assert!(reason.contains("out of range"));
        settings.clamp(&tank);
        assert!(settings.validate("", &tank).is_ok());
        settings.max_speed_m_per_s = f32::NAN;
        assert!(settings.validate("", &tank).is_err());
    }

    #[test]
    fn every_range_refuses_a_value_just_outside_and_clamps_it_to_the_bound() {
        let tank = Tank::default();
        crate::settings::number::check_table(
            &TankSettings::with_preset(Preset::Group),
            "left.",
            &TankSettings::NUMBERS,
            |s| s.validate("left.", &tank),
            |s| s.clamp(&tank),
        );
    }
}
