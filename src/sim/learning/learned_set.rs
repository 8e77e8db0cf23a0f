//! Saving and loading what a fish learned (TT §4): the raw learned controls of each
//! drill and their abstracted, measured controllers, as versioned JSON. A file is
//! checked completely before anything is used: wrong version, damaged JSON, wrong
//! array sizes, non-finite or out-of-range numbers each give a [`LearnedSetError`]
//! that says what is wrong.

use serde::{Deserialize, Serialize};

use crate::sim::body::physical_fish::BodySpecies;
use crate::sim::learning::abstraction::{AbstractionSettings, abstract_controls};
use crate::sim::learning::annealing::{AnnealingSchedule, Trainer};
use crate::sim::learning::learned_motor::{
    LearnedController, LearnedMapError, LearnedMotorMap, MAX_MODES,
};
use crate::sim::learning::muscle_spline::MuscleSpline;
use crate::sim::learning::objective::{Task, TrainingSetup};
use crate::tr;

/// Version written by this code and the only one read.
pub const FORMAT_VERSION: u32 = 1;
/// Largest file accepted, bytes (10 MB: a set of a few dozen drills is ~100 kB).
pub const MAX_FILE_BYTES: usize = 10_000_000;

/// The learned controls of one drill (before abstraction).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TrainedDrill {
    pub controller: LearnedController,
    /// The best learned controls u(t) of the drill.
    pub controls: MuscleSpline,
    /// Their objective E.
    pub objective: f32,
    /// Annealing steps spent.
    pub annealing_steps: u64,
}

impl TrainedDrill {
    /// Abstracts the best controls of `trainer` and measures the result (the
    /// second phase of §4: call it when the low-level learning is done).
    pub fn from_trainer(trainer: &Trainer, settings: &AbstractionSettings) -> Self {
        let setup = trainer.setup();
        let abstraction = abstract_controls(trainer.best_controls(), settings);
        Self {
            controller: LearnedController::measured(
                setup.task,
                abstraction.controller,
                setup.species,
                setup.body,
            ),
            controls: trainer.best_controls().clone(),
            objective: trainer.best_evaluation().objective,
            annealing_steps: trainer.evaluations(),
        }
    }
}

/// The routine drills of §4.3 ("swimming forward at different speeds and
/// executing turns of different radii"): as far as possible, 0.1 and 0.2 body
/// lengths per second straight ahead, and turns of 15 and 30 degrees per second to
/// either side at 0.2 body lengths per second (chosen: learned turns reach about a
/// third of the requested rate in 2000 steps, measured 9–10°/s for 20–40°/s; the
/// hand-tuned 90° turn makes 12°/s).
pub fn routine_drills() -> Vec<Task> {
    let turn = |rate: f32| Task::TurnHeading {
        turn_rate_deg_per_sec: rate,
        speed_body_lengths_per_sec: 0.2,
    };
    vec![
        Task::SWIM_FAR,
        Task::HoldSpeed {
            speed_body_lengths_per_sec: 0.1,
        },
        Task::HoldSpeed {
            speed_body_lengths_per_sec: 0.2,
        },
        turn(15.0),
        turn(30.0),
        turn(-15.0),
        turn(-30.0),
    ]
}

/// Trains every task of `tasks` from a brain-dead start (seeds `seed`, `seed` + 1,
/// …) for `schedule.planned_evaluations` steps each and abstracts them: the whole
/// of §4 in one call (about 2.6 ms per step natively in release with the default
/// setup). The UI does the same incrementally with [`Trainer`] and
/// [`TrainedDrill::from_trainer`].
pub fn train_set(
    base: TrainingSetup,
    tasks: &[Task],
    schedule: AnnealingSchedule,
    abstraction: &AbstractionSettings,
    seed: u64,
) -> LearnedControllerSet {
    let drills = tasks
        .iter()
        .enumerate()
        .map(|(k, &task)| {
            let mut trainer =
                Trainer::new(TrainingSetup { task, ..base }, schedule, seed + k as u64);
            trainer.run_evaluations(schedule.planned_evaluations as usize);
            TrainedDrill::from_trainer(&trainer, abstraction)
        })
        .collect();
    LearnedControllerSet::new(base.species, drills)
}

/// The shipped set: [`routine_drills`] learned by a fish with the default setup,
/// schedule (6840 steps each) and abstraction, seeds 1 to 7. Regenerate with
/// `SHOAL_WRITE_PRETRAINED=1 cargo test --release --lib pretrained_set_is_reproducible -- --ignored`.
pub const PRETRAINED_JSON: &str = include_str!("pretrained_fish.json");

/// What one fish learned: its species and its drills.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LearnedControllerSet {
    /// [`FORMAT_VERSION`].
    pub version: u32,
    pub species: BodySpecies,
    pub drills: Vec<TrainedDrill>,
}

/// Why a file could not be loaded.
#[derive(Debug)]
pub enum LearnedSetError {
    TooLarge,
    Json(serde_json::Error),
    WrongVersion { found: u32, expected: u32 },
    BadControls { drill: usize },
    BadController { drill: usize },
    NonFinite { drill: usize },
    Map(LearnedMapError),
}

impl From<serde_json::Error> for LearnedSetError {
    fn from(e: serde_json::Error) -> Self {
        Self::Json(e)
    }
}

impl From<LearnedMapError> for LearnedSetError {
    fn from(e: LearnedMapError) -> Self {
        Self::Map(e)
    }
}

impl std::fmt::Display for LearnedSetError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let text = match self {
            Self::TooLarge => tr!("learning-set-too-large", max = MAX_FILE_BYTES),
            Self::Json(e) => tr!("learning-set-not-a-set", reason = e.to_string()),
            Self::WrongVersion { found, expected } => tr!(
                "learning-set-wrong-version",
                found = *found,
                expected = *expected
            ),
            Self::BadControls { drill } => tr!("learning-set-bad-controls", drill = *drill),
            Self::BadController { drill } => tr!(
                "learning-set-bad-controller",
                drill = *drill,
                max = MAX_MODES
            ),
            Self::NonFinite { drill } => tr!("learning-set-non-finite", drill = *drill),
            Self::Map(e) => tr!("learning-set-map", reason = e.to_string()),
        };
        f.write_str(&text)
    }
}

impl std::error::Error for LearnedSetError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Json(e) => Some(e),
            Self::Map(e) => Some(e),
            _ => None,
        }
    }
}

impl LearnedControllerSet {
    pub fn new(species: BodySpecies, drills: Vec<TrainedDrill>) -> Self {
        Self {
            version: FORMAT_VERSION,
            species,
            drills,
        }
    }

    /// Pretty JSON.
    pub fn to_json(&self) -> Result<String, LearnedSetError> {
        Ok(serde_json::to_string_pretty(self)?)
    }

    /// Reads and validates a file's text.
    pub fn from_json(text: &str) -> Result<Self, LearnedSetError> {
        if text.len() > MAX_FILE_BYTES {
            return Err(LearnedSetError::TooLarge);
        }
        // Check the version first, so an old or new file says so rather than
        // failing on a field it does not know.
        #[derive(Deserialize)]
        struct VersionOnly {
            version: u32,
        }
        let v: VersionOnly = serde_json::from_str(text)?;
        if v.version != FORMAT_VERSION {
            return Err(LearnedSetError::WrongVersion {
                found: v.version,
                expected: FORMAT_VERSION,
            });
        }
        let set: Self = serde_json::from_str(text)?;
        set.validate()?;
        Ok(set)
    }

    /// Every check of [`Self::from_json`] after parsing.
    pub fn validate(&self) -> Result<(), LearnedSetError> {
        for (drill, d) in self.drills.iter().enumerate() {
            if !d.controls.is_valid() {
                return Err(LearnedSetError::BadControls { drill });
            }
            let c = &d.controller.controller;
            if !c.is_valid() || c.modes.len() > MAX_MODES {
                return Err(LearnedSetError::BadController { drill });
            }
            let m = d.controller.motion;
            if !(m.speed_body_lengths_per_sec.is_finite()
                && m.turn_rate_deg_per_sec.is_finite()
                && d.objective.is_finite())
            {
                return Err(LearnedSetError::NonFinite { drill });
            }
        }
        Ok(())
    }

    /// The shipped set ([`PRETRAINED_JSON`]).
    pub fn pretrained() -> Result<Self, LearnedSetError> {
        Self::from_json(PRETRAINED_JSON)
    }

    /// Compact JSON (what [`PRETRAINED_JSON`] holds).
    pub fn to_compact_json(&self) -> Result<String, LearnedSetError> {
        Ok(serde_json::to_string(self)?)
    }

    /// The speed and steering map of the set's drills.
    pub fn motor_map(&self) -> Result<LearnedMotorMap, LearnedSetError> {
        let controllers: Vec<LearnedController> =
            self.drills.iter().map(|d| d.controller.clone()).collect();
        Ok(LearnedMotorMap::new(&controllers)?)
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::learning::learned_set::*;

    /// The shipped set's recipe.
    pub(crate) fn pretrained_recipe() -> LearnedControllerSet {
        train_set(
            TrainingSetup::default(),
            &routine_drills(),
            AnnealingSchedule::default(),
            &AbstractionSettings::default(),
            1,
        )
    }

    #[test]
    #[ignore = "trains seven drills of 6840 steps: about 2 minutes in release"]
    fn pretrained_set_is_reproducible() {
        let set = pretrained_recipe();
        let json = set.to_compact_json().expect("serialises");
        if std::env::var("SHOAL_WRITE_PRETRAINED").is_ok() {
            let path = concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/src/sim/learning/pretrained_fish.json"
            );
            std::fs::write(path, &json).expect("writes the file");
        } else {
            assert_eq!(LearnedControllerSet::pretrained().expect("loads"), set);
        }
    }
}

#[cfg(test)]
mod file_tests {
    use crate::sim::learning::learned_set::*;
    use serde_json::{Value, json};

    fn shipped() -> LearnedControllerSet {
        LearnedControllerSet::pretrained().expect("the shipped set loads")
    }

    /// The shipped set as JSON, changed by `edit`, loaded.
    fn load_edited(edit: impl FnOnce(&mut Value)) -> Result<LearnedControllerSet, LearnedSetError> {
        let mut v: Value = serde_json::from_str(PRETRAINED_JSON).expect("valid JSON");
        edit(&mut v);
        LearnedControllerSet::from_json(&v.to_string())
    }

    #[test]
    fn a_set_survives_saving_and_loading() {
        let set = shipped();
        assert_eq!(set.version, FORMAT_VERSION);
        assert!(!set.drills.is_empty());
        let pretty = set.to_json().expect("serialises");
        assert_eq!(
            LearnedControllerSet::from_json(&pretty).expect("loads"),
            set
        );
        assert!(set.motor_map().is_ok());
    }

    #[test]
    fn bad_files_say_what_is_wrong() {
        let garbage = LearnedControllerSet::from_json("this is not JSON {");
        assert!(matches!(garbage, Err(LearnedSetError::Json(_))));
        let other = LearnedControllerSet::from_json(r#"{"name": "a cat"}"#);
        assert!(matches!(other, Err(LearnedSetError::Json(_))));
        let version = load_edited(|v| v["version"] = json!(2));
        assert!(matches!(
            version,
            Err(LearnedSetError::WrongVersion {
                found: 2,
                expected: 1
            })
        ));
        // A sample with 11 muscles instead of 12.
        let short = load_edited(|v| {
            if let Some(s) = v["drills"][0]["controls"]["samples"][0].as_array_mut() {
                s.pop();
            }
        });
        assert!(matches!(short, Err(LearnedSetError::Json(_))), "{short:?}");
        // A contraction outside [0, 1], and one too large for an f32 (infinite).
        let outside = load_edited(|v| v["drills"][1]["controls"]["samples"][2][3] = json!(1.5));
        assert!(matches!(
            outside,
            Err(LearnedSetError::BadControls { drill: 1 })
        ));
        let infinite = load_edited(|v| v["drills"][0]["controls"]["samples"][0][0] = json!(1e39));
        assert!(matches!(
            infinite,
            Err(LearnedSetError::BadControls { drill: 0 })
        ));
        let one_sample = load_edited(|v| {
            if let Some(s) = v["drills"][0]["controls"]["samples"].as_array_mut() {
                s.truncate(1);
            }
        });
        assert!(matches!(
            one_sample,
            Err(LearnedSetError::BadControls { drill: 0 })
        ));
        // NaN cannot be written in JSON: serde_json writes null, which is refused.
        let nan = load_edited(|v| v["drills"][0]["objective"] = Value::Null);
        assert!(matches!(nan, Err(LearnedSetError::Json(_))));
        let huge_rate = load_edited(|v| {
            v["drills"][0]["controller"]["motion"]["turn_rate_deg_per_sec"] = json!(-1e39)
        });
        assert!(matches!(
            huge_rate,
            Err(LearnedSetError::NonFinite { drill: 0 })
        ));
        let too_many_modes = load_edited(|v| {
            let modes = &mut v["drills"][0]["controller"]["controller"]["modes"];
            let first = modes[0].clone();
            if let Some(m) = modes.as_array_mut() {
                m.extend(std::iter::repeat_n(first, MAX_MODES));
            }
        });
        assert!(matches!(
            too_many_modes,
            Err(LearnedSetError::BadController { drill: 0 })
        ));
        // Every message is a sentence a teacher can read.
        let message = version.err().map(|e| e.to_string()).unwrap_or_default();
        assert!(message.contains("version 2"), "{message}");
    }

    #[test]
    fn a_set_without_a_straight_swim_cannot_drive_a_fish() {
        let mut set = shipped();
        set.drills
            .retain(|d| matches!(d.controller.task, Task::TurnHeading { .. }));
        assert!(matches!(
            set.motor_map(),
            Err(LearnedSetError::Map(LearnedMapError::NoStraightController))
        ));
    }

    #[test]
    fn straight_swims_keep_ninety_percent_of_their_energy_in_two_modes() {
        let settings = AbstractionSettings::default();
        assert_eq!(settings.modes, 2);
        let set = shipped();
        let mut straight = 0;
        for d in &set.drills {
            if matches!(d.controller.task, Task::TurnHeading { .. }) {
                continue;
            }
            straight += 1;
            let a = abstract_controls(&d.controls, &settings);
            assert!(a.controller.modes.len() <= 2);
            assert!(
                a.controller.energy_fraction >= 0.9,
                "{:?}: {:.3}",
                d.controller.task,
                a.controller.energy_fraction
            );
            assert_eq!(
                a.controller, d.controller.controller,
                "the file holds this abstraction"
            );
        }
        assert_eq!(straight, 3);
    }
}

#[cfg(test)]
mod live_tests {
    use crate::sim::body::BodyParams;
    use crate::sim::learning::learned_motor::{LearnedMotor, MEASURE_SECS, measure_motion_with};
    use crate::sim::learning::learned_set::*;

    /// The whole of §4 live, on a small budget: two drills of 1000 steps from a
    /// brain-dead start, abstracted, mapped, driven. Seeds 4 (straight) and 5
    /// (turn). Not every seed learns a lasting turn in 1000–1500 steps: with seed 6
    /// the fish learns a one-off 43° swerve from rest that the periodic abstraction
    /// does not keep (−1°/s), see docs/learning.md.
    #[test]
    fn a_brain_dead_fish_learns_to_swim_and_to_turn_left() {
        let steps = 1000;
        let schedule = AnnealingSchedule {
            planned_evaluations: steps,
            ..AnnealingSchedule::default()
        };
        let tasks = [
            Task::SWIM_FAR,
            Task::TurnHeading {
                turn_rate_deg_per_sec: 30.0,
                speed_body_lengths_per_sec: 0.2,
            },
        ];
        let base = TrainingSetup::default();
        let set = train_set(base, &tasks, schedule, &AbstractionSettings::default(), 4);
        let map = set.motor_map().expect("a straight swim was learned");
        let params = BodyParams::default();
        let measure = |speed: f32, turn: f32| {
            let motor = LearnedMotor::new(map.clone());
            measure_motion_with(BodySpecies::Fish, params, MEASURE_SECS, |t| {
                motor.muscles_at(speed, turn, t)
            })
        };
        let (straight, left, right) = (measure(1.0, 0.0), measure(1.0, 1.0), measure(1.0, -1.0));
        assert!(straight.speed_body_lengths_per_sec > 0.15, "{straight:?}");
        let s = straight.turn_rate_deg_per_sec;
        assert!(
            left.turn_rate_deg_per_sec > s + 3.0,
            "left {left:?}, straight {straight:?}"
        );
        // The right turn is the mirror image of the learned left one.
        assert!(
            right.turn_rate_deg_per_sec < s - 3.0,
            "right {right:?}, straight {straight:?}"
        );
    }
}
