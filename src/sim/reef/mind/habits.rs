//! The innate character of an artificial fish (Tu & Terzopoulos 1994 §6.1, §6.3,
//! §7): its type (predator, prey or pacifist), sex, what light and water it
//! likes, whether it schools, and the two personality knobs of §6.2–6.3: the
//! collision-sensitivity box ("timid" versus "courageous") and the persistence
//! threshold ("fickle" versus "devoted").

use serde::{Deserialize, Serialize};

use crate::sim::reef::mind::mental_state::{
    CALM_DIGESTION_RATE, CALM_LIBIDO_RATE, MentalConstants,
};

/// The three kinds of artificial fish of §7.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FishKind {
    /// Hunts prey; feels no fear and no libido; never leaves (§7.1).
    Predator,
    /// Schools and escapes predators; does not mate (§7.2).
    Prey,
    /// Eats and courts; does not school or escape (§7.3).
    Pacifist,
}

impl FishKind {
    pub const ALL: [Self; 3] = [Self::Predator, Self::Prey, Self::Pacifist];

    pub fn label(self) -> &'static str {
        match self {
            Self::Predator => "predator",
            Self::Prey => "prey",
            Self::Pacifist => "pacifist",
        }
    }
}

/// Male or female.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Sex {
    Male,
    Female,
}

/// A liking for one end of an ambient scale (light or temperature).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Liking {
    /// Content anywhere.
    #[default]
    Indifferent,
    /// Wants the high end (bright water, warm water).
    High,
    /// Wants the low end (dark water, cold water).
    Low,
}

impl Liking {
    /// Is a fish with this liking content at `value` (0 = low end, 1 = high)?
    /// It is when the value is on its side of the middle, with a dead band of
    /// [`CONTENT_BAND`] so a fish at the border does not dither.
    pub fn content_at(self, value: f32) -> bool {
        match self {
            Self::Indifferent => true,
            Self::High => value >= 0.5 - CONTENT_BAND,
            Self::Low => value <= 0.5 + CONTENT_BAND,
        }
    }
}

/// Half-width of the neutral band around the middle of an ambient scale (0.1,
/// chosen: a fish that likes warmth tolerates water a little below lukewarm).
pub const CONTENT_BAND: f32 = 0.1;

/// The habits and personality of one fish.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Habits {
    pub kind: FishKind,
    pub sex: Sex,
    /// A species number; same-species partners are preferred in courtship.
    pub species: u8,
    /// Likes bright or dark water.
    pub light: Liking,
    /// Likes warm or cold water.
    pub temperature: Liking,
    /// Schools when not hungry and not threatened (prey).
    pub schools: bool,
    /// Length of the collision-sensitivity box ahead of the head, body lengths.
    /// "Timid" 1.5, default 0.8, "courageous" 0.3 (chosen).
    pub collision_box_ahead_body_lengths: f32,
    /// Persistence threshold, body lengths: a new target replaces the current
    /// one only if it is closer by more than this. "Fickle" 0, "devoted" 20.
    pub persistence_body_lengths: f32,
    /// Hunger, libido and fear constants.
    pub mental: MentalConstants,
    /// f0: fear above this is evasive action (paper: 0.1 ≤ f0 ≤ 0.5). 0.3, chosen.
    pub fear_threshold: f32,
    /// f1 > f0: the most dangerous predator's fear above this means escape,
    /// below it a schooling fish schools. 0.8 (a public re-implementation's value).
    pub panic_threshold: f32,
    /// r: the larger of hunger and libido above this means eat or mate
    /// (paper: 0 < r < 0.5). 0.25 (the re-implementation's value).
    pub urge_threshold: f32,
}

/// Collision box of a timid fish, body lengths.
pub const TIMID_BOX_BODY_LENGTHS: f32 = 1.5;
/// Collision box of an ordinary fish, body lengths.
pub const DEFAULT_BOX_BODY_LENGTHS: f32 = 0.8;
/// Collision box of a courageous fish, body lengths.
pub const COURAGEOUS_BOX_BODY_LENGTHS: f32 = 0.3;
/// Persistence of a fickle fish, body lengths.
pub const FICKLE_BODY_LENGTHS: f32 = 0.0;
/// Persistence of an ordinary fish, body lengths.
pub const DEFAULT_PERSISTENCE_BODY_LENGTHS: f32 = 2.0;
/// Persistence of a devoted fish, body lengths.
pub const DEVOTED_BODY_LENGTHS: f32 = 20.0;

impl Habits {
    /// An ordinary fish of `kind`: appetite by kind (predators 4 food units, one
    /// prey; others 3 plankton particles), Shoal's calm default p0 and p1
    /// (`MentalConstants::shoal_default`).
    pub fn new(kind: FishKind, sex: Sex, species: u8) -> Self {
        let appetite = match kind {
            FishKind::Predator => crate::sim::reef::mind::mental_state::PREY_FOOD_UNITS,
            FishKind::Prey | FishKind::Pacifist => 3.0,
        };
        Self {
            kind,
            sex,
            species,
            light: Liking::Indifferent,
            temperature: Liking::Indifferent,
            schools: kind == FishKind::Prey,
            collision_box_ahead_body_lengths: DEFAULT_BOX_BODY_LENGTHS,
            persistence_body_lengths: DEFAULT_PERSISTENCE_BODY_LENGTHS,
            mental: MentalConstants::shoal_default(appetite),
            fear_threshold: 0.3,
            panic_threshold: 0.8,
            urge_threshold: 0.25,
        }
    }

    /// Clamps every number into its documented range (NaN → default), so a
    /// tampered setting cannot break the mind.
    pub fn sanitized(mut self) -> Self {
        let fix = |v: f32, lo: f32, hi: f32, default: f32| {
            if v.is_finite() {
                v.clamp(lo, hi)
            } else {
                default
            }
        };
        self.collision_box_ahead_body_lengths = fix(
            self.collision_box_ahead_body_lengths,
            0.1,
            3.0,
            DEFAULT_BOX_BODY_LENGTHS,
        );
        self.persistence_body_lengths = fix(
            self.persistence_body_lengths,
            0.0,
            50.0,
            DEFAULT_PERSISTENCE_BODY_LENGTHS,
        );
        self.fear_threshold = fix(self.fear_threshold, 0.1, 0.5, 0.3);
        self.panic_threshold = fix(self.panic_threshold, self.fear_threshold, 1.0, 0.8);
        self.urge_threshold = fix(self.urge_threshold, 0.01, 0.5, 0.25);
        let m = &mut self.mental;
        m.digestion_rate_per_unit = fix(m.digestion_rate_per_unit, 0.0, 0.05, CALM_DIGESTION_RATE);
        m.libido_rate_per_unit = fix(m.libido_rate_per_unit, 0.0, 0.05, CALM_LIBIDO_RATE);
        m.appetite_food_units = fix(m.appetite_food_units, 0.5, 20.0, 3.0);
        m.fear_distance_body_lengths = fix(m.fear_distance_body_lengths, 0.1, 20.0, 3.85);
        self
    }
}

/// A teacher's changes to the minds of one kind of fish (the reef's *Minds*
/// panel, `reef.traits` in the settings): each value given replaces what the
/// demo chose for every fish of the kind; `None` keeps the demo's own. Names
/// are those of [`Habits`] and [`MentalConstants`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct MindTraits {
    /// p0, digestion rate per paper time unit (1/40 s): nominal 0.00067,
    /// "ravenous" 0.005. Links made before the one clock call it
    /// `digestion_rate_per_step`.
    #[serde(alias = "digestion_rate_per_step")]
    pub digestion_rate_per_unit: Option<f32>,
    /// p1, libido growth per paper time unit (1/40 s): nominal 0.0025, "sexual
    /// mania" 0.01. Old links: `libido_rate_per_step`.
    #[serde(alias = "libido_rate_per_step")]
    pub libido_rate_per_unit: Option<f32>,
    /// α, appetite in food units.
    pub appetite_food_units: Option<f32>,
    /// D0, fear distance in body lengths (paper 3.85).
    pub fear_distance_body_lengths: Option<f32>,
    /// Collision box ahead, body lengths: "timid" 1.5, ordinary 0.8,
    /// "courageous" 0.3.
    pub collision_box_ahead_body_lengths: Option<f32>,
    /// Persistence threshold, body lengths: "fickle" 0, ordinary 2,
    /// "devoted" 20.
    pub persistence_body_lengths: Option<f32>,
    /// f0, the fear above which a fish takes evasive action.
    pub fear_threshold: Option<f32>,
    /// f1, the fear of the worst predator above which a schooling fish
    /// escapes instead of schooling.
    pub panic_threshold: Option<f32>,
    /// r, the hunger or libido above which a fish eats or mates.
    pub urge_threshold: Option<f32>,
}

impl MindTraits {
    /// `habits` with every value given here put in (and kept in range).
    pub fn applied_to(&self, mut habits: Habits) -> Habits {
        let mut given = *self;
        for (value, fish) in given.beside(&mut habits) {
            if let Some(v) = *value {
                *fish = v;
            }
        }
        habits.sanitized()
    }

    /// The traits `habits` has, every one given: applied to a fish, they give
    /// it every number of `habits` (the reef's *Minds* panel draws its rows
    /// over those of the demo's own fish with the teacher's changes).
    pub fn of_fish(habits: &Habits) -> Self {
        let mut traits = Self::default();
        let mut habits = *habits;
        for (value, fish) in traits.beside(&mut habits) {
            *value = Some(*fish);
        }
        traits
    }

    /// Each trait beside the number of a fish it replaces. (Their ranges,
    /// words and named values, as settings: `MindTraits::NUMBERS`, in
    /// `settings/minds.rs`.)
    fn beside<'a>(&'a mut self, h: &'a mut Habits) -> [(&'a mut Option<f32>, &'a mut f32); 9] {
        let m = &mut h.mental;
        [
            (
                &mut self.digestion_rate_per_unit,
                &mut m.digestion_rate_per_unit,
            ),
            (&mut self.libido_rate_per_unit, &mut m.libido_rate_per_unit),
            (&mut self.appetite_food_units, &mut m.appetite_food_units),
            (
                &mut self.fear_distance_body_lengths,
                &mut m.fear_distance_body_lengths,
            ),
            (
                &mut self.collision_box_ahead_body_lengths,
                &mut h.collision_box_ahead_body_lengths,
            ),
            (
                &mut self.persistence_body_lengths,
                &mut h.persistence_body_lengths,
            ),
            (&mut self.fear_threshold, &mut h.fear_threshold),
            (&mut self.panic_threshold, &mut h.panic_threshold),
            (&mut self.urge_threshold, &mut h.urge_threshold),
        ]
    }
}

/// [`MindTraits`] for each kind of fish.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct KindTraits {
    pub predator: MindTraits,
    pub prey: MindTraits,
    pub pacifist: MindTraits,
}

impl KindTraits {
    pub fn of(&self, kind: FishKind) -> &MindTraits {
        match kind {
            FishKind::Predator => &self.predator,
            FishKind::Prey => &self.prey,
            FishKind::Pacifist => &self.pacifist,
        }
    }

    pub fn of_mut(&mut self, kind: FishKind) -> &mut MindTraits {
        match kind {
            FishKind::Predator => &mut self.predator,
            FishKind::Prey => &mut self.prey,
            FishKind::Pacifist => &mut self.pacifist,
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::reef::mind::habits::*;

    #[test]
    fn liking_has_a_dead_band() {
        assert!(Liking::High.content_at(0.45));
        assert!(!Liking::High.content_at(0.3));
        assert!(Liking::Low.content_at(0.55));
        assert!(!Liking::Low.content_at(0.7));
        assert!(Liking::Indifferent.content_at(0.0));
    }

    #[test]
    fn traits_replace_only_what_they_set() {
        let demo = Habits::new(FishKind::Predator, Sex::Male, 9);
        assert_eq!(MindTraits::default().applied_to(demo), demo);
        let ravenous = MindTraits {
            digestion_rate_per_unit: Some(
                crate::sim::reef::mind::mental_state::RAVENOUS_DIGESTION_RATE,
            ),
            persistence_body_lengths: Some(DEVOTED_BODY_LENGTHS),
            ..MindTraits::default()
        };
        let h = ravenous.applied_to(demo);
        assert_eq!(h.mental.digestion_rate_per_unit, 0.005);
        assert_eq!(h.persistence_body_lengths, 20.0);
        assert_eq!(
            h.mental.appetite_food_units,
            demo.mental.appetite_food_units
        );
        assert_eq!(h.fear_threshold, demo.fear_threshold);
    }

    #[test]
    fn a_fish_s_traits_give_every_value_and_make_the_fish_again() {
        let mut h = Habits::new(FishKind::Prey, Sex::Female, 2);
        h.mental.digestion_rate_per_unit = 0.001;
        h.mental.libido_rate_per_unit = 0.002;
        h.mental.appetite_food_units = 5.0;
        h.mental.fear_distance_body_lengths = 6.0;
        h.collision_box_ahead_body_lengths = 1.1;
        h.persistence_body_lengths = 7.0;
        h.fear_threshold = 0.2;
        h.panic_threshold = 0.6;
        h.urge_threshold = 0.3;
        let traits = MindTraits::of_fish(&h);
        let json = serde_json::to_value(traits).unwrap();
        let fields = json.as_object().unwrap();
        assert_eq!(fields.len(), 9);
        assert!(fields.values().all(|v| v.is_number()), "{json}");
        let other = Habits::new(FishKind::Prey, Sex::Female, 2);
        assert_eq!(traits.applied_to(other), h);
    }

    #[test]
    fn sanitized_clamps_and_replaces_nan() {
        let mut h = Habits::new(FishKind::Prey, Sex::Female, 0);
        h.fear_threshold = f32::NAN;
        h.panic_threshold = 0.05;
        h.mental.appetite_food_units = -3.0;
        let h = h.sanitized();
        assert_eq!(h.fear_threshold, 0.3);
        assert_eq!(h.panic_threshold, 0.3);
        assert_eq!(h.mental.appetite_food_units, 0.5);
        assert!(h.schools);
        assert!(!Habits::new(FishKind::Pacifist, Sex::Male, 1).schools);
    }
}
