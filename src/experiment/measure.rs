//! What an experiment measures ([`Measure`]: the school's metrics the plots
//! show, the reef's census) and how a run's samples become numbers
//! ([`Summary`]).

use crate::i18n::ts;
use crate::settings::Scene;
use crate::settings::number::static_id;

/// Measures and summaries travel by name (`"polarization"`, `"mean"`), as in
/// experiment files and the CSV.
macro_rules! serialize_by_name {
    ($t:ty) => {
        impl serde::Serialize for $t {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.serialize_str(self.name())
            }
        }
    };
}

serialize_by_name!(Measure);
serialize_by_name!(Summary);

/// What can be measured: the school's metrics the plots show, and the reef's
/// census counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Measure {
    Polarization,
    Milling,
    NndBodyLengths,
    Groups,
    MeanSpeed,
    /// How far the average fish of the school swam in the measuring window
    /// (metres): the fish's mean speed added up step by step (see
    /// [`crate::sim::SceneWorld::school_mean_speed_m_per_s`]).
    DistanceSwum,
    /// Prey caught by sharks (schooling lab) or predators (reef).
    Catches,
    FoodEaten,
    Spawnings,
    MissedStrikes,
    FishCollisions,
    PreyAlive,
}

impl Measure {
    pub const ALL: [Self; 12] = [
        Self::Polarization,
        Self::Milling,
        Self::NndBodyLengths,
        Self::Groups,
        Self::MeanSpeed,
        Self::DistanceSwum,
        Self::Catches,
        Self::FoodEaten,
        Self::Spawnings,
        Self::MissedStrikes,
        Self::FishCollisions,
        Self::PreyAlive,
    ];

    /// The name in experiment files and the CSV (the metrics CSV's column name).
    pub fn name(self) -> &'static str {
        match self {
            Self::Polarization => "polarization",
            Self::Milling => "milling",
            Self::NndBodyLengths => "nnd_body_lengths",
            Self::Groups => "groups",
            Self::MeanSpeed => "mean_speed_m_per_s",
            Self::DistanceSwum => "distance_swum_m",
            Self::Catches => "catches",
            Self::FoodEaten => "food_eaten",
            Self::Spawnings => "spawnings",
            Self::MissedStrikes => "missed_strikes",
            Self::FishCollisions => "fish_collisions",
            Self::PreyAlive => "prey_alive",
        }
    }

    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == name)
    }

    /// The catalogue's message of its words: the plots' own for the school's
    /// metrics (the side panel names them so), `experiment-measure-…` for the
    /// counts; each with `.help`.
    pub fn label_id(self) -> &'static str {
        match self {
            Self::Polarization => "metrics-polarization",
            Self::Milling => "metrics-milling",
            Self::NndBodyLengths => "metrics-nearest",
            Self::Groups => "metrics-groups",
            Self::MeanSpeed => "metrics-speed",
            Self::DistanceSwum => "experiment-measure-distance-swum",
            Self::Catches => "experiment-measure-catches",
            Self::FoodEaten => "experiment-measure-food-eaten",
            Self::Spawnings => "experiment-measure-spawnings",
            Self::MissedStrikes => "experiment-measure-missed-strikes",
            Self::FishCollisions => "experiment-measure-fish-collisions",
            Self::PreyAlive => "experiment-measure-prey-alive",
        }
    }

    /// Its name on screen, in the language in force ("Nearest neighbour
    /// (body lengths)"); [`Self::name`] is the files' and the CSV's.
    pub fn label(self) -> &'static str {
        ts(self.label_id())
    }

    /// What it measures, as a 12-year-old reads it (hover help).
    pub fn help(self) -> &'static str {
        ts(static_id(format!("{}.help", self.label_id())))
    }

    /// Counters of events (and the distance swum): their values count from the
    /// start of the measuring window, so the warm-up is not measured.
    pub fn is_counter(self) -> bool {
        matches!(
            self,
            Self::DistanceSwum
                | Self::Catches
                | Self::FoodEaten
                | Self::Spawnings
                | Self::MissedStrikes
                | Self::FishCollisions
        )
    }

    /// Does `scene` measure it ([`crate::scenes::SceneFacts::measures`])?
    pub fn available_in(self, scene: Scene) -> bool {
        scene.class().facts().measures.contains(&self)
    }
}

/// How a run's samples over the measuring window become the CSV's values.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Summary {
    /// The mean of the samples in the window.
    #[default]
    Mean,
    /// The last sample (for a counter: the events in the window).
    Final,
    /// Every sample, one row each, with its time.
    Series,
}

impl Summary {
    pub const ALL: [Self; 3] = [Self::Mean, Self::Final, Self::Series];

    pub fn name(self) -> &'static str {
        match self {
            Self::Mean => "mean",
            Self::Final => "final",
            Self::Series => "series",
        }
    }

    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|s| s.name() == name)
    }
}
