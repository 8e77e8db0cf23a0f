//! The reef's *Minds* settings (`reef.traits.<kind>.<trait>`): each trait a
//! teacher can change in a kind of fish's mind, described once in
//! [`MindTraits::NUMBERS`] — its range, label, hover help, unit, control,
//! rectangle and named values ("Calm", "Devoted"). The reef's settings validate
//! and clamp each kind's traits from it, the *Minds* panel draws each row from
//! it (`ui/reef_minds.rs`), the studio's rules name each row by its key and the
//! tests walk it. [`MindTraits`] itself, what the model reads, is the reef's
//! (`sim/reef/mind/habits.rs`).

use crate::settings::number::{NamedValue, Number, NumberSetting, Unit, Widget, field};
use crate::settings::range::Range;
use crate::sim::reef::mind::habits::{
    COURAGEOUS_BOX_BODY_LENGTHS, DEFAULT_BOX_BODY_LENGTHS, DEFAULT_PERSISTENCE_BODY_LENGTHS,
    DEVOTED_BODY_LENGTHS, FICKLE_BODY_LENGTHS, MindTraits, TIMID_BOX_BODY_LENGTHS,
};
use crate::sim::reef::mind::mental_state::{
    CALM_DIGESTION_RATE, CALM_LIBIDO_RATE, MANIC_LIBIDO_RATE, NOMINAL_DIGESTION_RATE,
    NOMINAL_LIBIDO_RATE, RAVENOUS_DIGESTION_RATE,
};
use crate::sim::reef::mind::{FishKind, Habits, Sex};

/// An ordinary prey fish: what a trait left unset reads as where no demo's
/// fish is at hand. (In the reef an unset trait is the demo's own fish's, and
/// the *Minds* panel draws its rows over those: [`MindTraits::of_fish`].)
fn ordinary() -> Habits {
    Habits::new(FishKind::Prey, Sex::Female, 0)
}

impl MindTraits {
    pub const DIGESTION_RATE: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "minds",
        Range::new("digestion_rate_per_unit", 0.0, 0.05),
        field!(digestion_rate_per_unit, |_| ordinary()
            .mental
            .digestion_rate_per_unit),
    )
    .widget(Widget::LOG_SLIDER)
    .rect("reef_minds_hunger")
    .named(&[
        NamedValue::new("calm", CALM_DIGESTION_RATE),
        NamedValue::new("nominal", NOMINAL_DIGESTION_RATE),
        NamedValue::new("ravenous", RAVENOUS_DIGESTION_RATE),
    ]);
    pub const LIBIDO_RATE: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "minds",
        Range::new("libido_rate_per_unit", 0.0, 0.05),
        field!(libido_rate_per_unit, |_| ordinary()
            .mental
            .libido_rate_per_unit),
    )
    .widget(Widget::LOG_SLIDER)
    .rect("reef_minds_libido")
    .named(&[
        NamedValue::new("calm", CALM_LIBIDO_RATE),
        NamedValue::new("nominal", NOMINAL_LIBIDO_RATE),
        NamedValue::new("sexual-mania", MANIC_LIBIDO_RATE),
    ]);
    pub const APPETITE: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "minds",
        Range::new("appetite_food_units", 0.5, 20.0),
        field!(appetite_food_units, |_| ordinary()
            .mental
            .appetite_food_units),
    )
    .unit(Unit::Food)
    .rect("reef_minds_appetite");
    pub const FEAR_DISTANCE: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "minds",
        Range::new("fear_distance_body_lengths", 0.1, 20.0),
        field!(fear_distance_body_lengths, |_| ordinary()
            .mental
            .fear_distance_body_lengths),
    )
    .unit(Unit::BodyLengths)
    .rect("reef_minds_fear_distance");
    pub const COLLISION_BOX: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "minds",
        Range::new("collision_box_ahead_body_lengths", 0.1, 3.0),
        field!(collision_box_ahead_body_lengths, |_| ordinary()
            .collision_box_ahead_body_lengths),
    )
    .widget(Widget::NamedOnly)
    .rect("reef_minds_box")
    .named(&[
        NamedValue::new("timid", TIMID_BOX_BODY_LENGTHS),
        NamedValue::new("ordinary", DEFAULT_BOX_BODY_LENGTHS),
        NamedValue::new("courageous", COURAGEOUS_BOX_BODY_LENGTHS),
    ]);
    pub const PERSISTENCE: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "minds",
        Range::new("persistence_body_lengths", 0.0, 50.0),
        field!(persistence_body_lengths, |_| ordinary()
            .persistence_body_lengths),
    )
    .widget(Widget::NamedOnly)
    .rect("reef_minds_persistence")
    .named(&[
        NamedValue::new("fickle", FICKLE_BODY_LENGTHS),
        NamedValue::new("ordinary", DEFAULT_PERSISTENCE_BODY_LENGTHS),
        NamedValue::new("devoted", DEVOTED_BODY_LENGTHS),
    ]);
    pub const FEAR_THRESHOLD: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "minds",
        Range::new("fear_threshold", 0.1, 0.5),
        field!(fear_threshold, |_| ordinary().fear_threshold),
    )
    .rect("reef_minds_alarm");
    pub const PANIC_THRESHOLD: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "minds",
        Range::new("panic_threshold", 0.5, 1.0),
        field!(panic_threshold, |_| ordinary().panic_threshold),
    )
    .rect("reef_minds_panic");
    pub const URGE_THRESHOLD: NumberSetting<Self, f32> = NumberSetting::<Self, _>::new(
        "minds",
        Range::new("urge_threshold", 0.01, 0.5),
        field!(urge_threshold, |_| ordinary().urge_threshold),
    )
    .rect("reef_minds_urge");

    /// Every trait, in the order validation reports them. The ranges are those
    /// [`Habits::sanitized`] keeps (f0 and r within the paper's 0.1–0.5 and
    /// 0–0.5); an unset trait is the demo's own fish's.
    pub const NUMBERS: [Number<Self>; 9] = [
        Number::F32(Self::DIGESTION_RATE),
        Number::F32(Self::LIBIDO_RATE),
        Number::F32(Self::APPETITE),
        Number::F32(Self::FEAR_DISTANCE),
        Number::F32(Self::COLLISION_BOX),
        Number::F32(Self::PERSISTENCE),
        Number::F32(Self::FEAR_THRESHOLD),
        Number::F32(Self::PANIC_THRESHOLD),
        Number::F32(Self::URGE_THRESHOLD),
    ];

    /// The traits that change how `kind` behaves, as the *Minds* panel lists
    /// them: predators feel no fear and no libido, only prey school (and panic
    /// out of the school), only pacifists court.
    pub fn shown_for(kind: FishKind) -> &'static [NumberSetting<Self, f32>] {
        match kind {
            FishKind::Predator => &[
                Self::DIGESTION_RATE,
                Self::APPETITE,
                Self::URGE_THRESHOLD,
                Self::COLLISION_BOX,
                Self::PERSISTENCE,
            ],
            FishKind::Prey => &[
                Self::DIGESTION_RATE,
                Self::APPETITE,
                Self::FEAR_DISTANCE,
                Self::FEAR_THRESHOLD,
                Self::PANIC_THRESHOLD,
                Self::URGE_THRESHOLD,
                Self::COLLISION_BOX,
                Self::PERSISTENCE,
            ],
            FishKind::Pacifist => &[
                Self::DIGESTION_RATE,
                Self::LIBIDO_RATE,
                Self::APPETITE,
                Self::FEAR_DISTANCE,
                Self::FEAR_THRESHOLD,
                Self::URGE_THRESHOLD,
                Self::COLLISION_BOX,
                Self::PERSISTENCE,
            ],
        }
    }

    /// The key prefix of `kind`'s traits under the reef's `prefix` ("reef."
    /// gives "reef.traits.prey."), as `shoal.set`, share links and the
    /// studio's rules name them.
    pub fn prefix(prefix: &str, kind: FishKind) -> String {
        format!("{prefix}traits.{}.", kind.label())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::number::{check_all, check_table, clamp_all};

    #[test]
    fn every_range_refuses_a_value_just_outside_and_clamps_it_to_the_bound() {
        let prefix = "reef.traits.prey.";
        // Every trait given, so a trait missing from the table is caught.
        let every = MindTraits::of_fish(&ordinary());
        check_table(
            &every,
            prefix,
            &MindTraits::NUMBERS,
            |t| check_all(&MindTraits::NUMBERS, prefix, t),
            |t| clamp_all(&MindTraits::NUMBERS, t),
        );
    }

    #[test]
    fn each_bound_reaches_the_fish_and_a_non_number_is_the_demo_s_own() {
        for kind in FishKind::ALL {
            let demo = Habits::new(kind, Sex::Male, 3);
            for number in &MindTraits::NUMBERS {
                let Number::F32(setting) = number else {
                    panic!("{}: a trait is an f32", number.key());
                };
                for bound in [setting.range.min, setting.range.max] {
                    let mut traits = MindTraits::default();
                    setting.set(&mut traits, bound);
                    let fish = MindTraits::of_fish(&traits.applied_to(demo));
                    assert_eq!(setting.given(&fish), Some(bound), "{}", number.key());
                }
                let mut traits = MindTraits::default();
                setting.set(&mut traits, f32::NAN);
                number.clamp(&mut traits);
                assert_eq!(traits, MindTraits::default(), "{}", number.key());
            }
        }
    }

    #[test]
    fn every_trait_is_shown_for_some_kind_and_named_values_are_in_range() {
        for number in &MindTraits::NUMBERS {
            let Number::F32(setting) = number else {
                panic!("{}: a trait is an f32", number.key());
            };
            let shown = FishKind::ALL.iter().any(|&kind| {
                MindTraits::shown_for(kind)
                    .iter()
                    .any(|s| s.range.key == setting.range.key)
            });
            assert!(shown, "{} is shown for some kind", number.key());
            for named in setting.named {
                assert!(setting.range.contains(named.value), "{}", named.name);
            }
            if setting.widget == Widget::NamedOnly {
                assert!(!setting.named.is_empty(), "{}", number.key());
            }
        }
    }
}
