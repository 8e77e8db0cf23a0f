//! The "Learning lab" scene's simulation: a brain-dead fish practises the routine
//! drills one after another by simulated annealing (TT §4.2), each finished drill
//! is abstracted (§4.3), and when all are done the learned speed and steering map
//! drives a fish between two buoys (Fig. 9); the sharks snapshotted during the
//! first drill race (Fig. 7). Training advances only when asked
//! ([`LearningLab::train`]), so the app spreads it over frames; the demo fish and
//! the race advance one body step per [`LearningLab::step`].
//!
//! The demo fish swims with the controllers the teacher picks: the hand-tuned
//! swim-MC and turn-MC (`body/`), or the learned map of the set in use (loaded
//! from a file, else trained here, else the shipped pre-trained set).

use glam::Vec3;
use serde::{Deserialize, Serialize};

use crate::sim::body::motor_bridge::to_tank_frame;
use crate::sim::body::physical_fish::{BodySpecies, PhysicalFish};
use crate::sim::body::{BodyParams, NODE_COUNT};
use crate::sim::common::tank::Tank;
use crate::sim::learning::abstraction::{Abstraction, AbstractionSettings, abstract_controls};
use crate::sim::learning::annealing::{AnnealingSchedule, Trainer};
use crate::sim::learning::learned_set::{
    LearnedControllerSet, LearnedSetError, TrainedDrill, routine_drills,
};
use crate::sim::learning::objective::{Task, TrainingSetup};
use crate::sim::learning::race::{PAPER_RACE_STEPS, Race, RaceEntrant};
use crate::sim::learning::target_tracking::BuoyTracker;

/// Which controllers drive the demo fish.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ControllerChoice {
    /// The hand-tuned swim-MC and turn-MC of the body.
    HandTuned,
    /// The learned speed and steering map.
    #[default]
    Learned,
}

/// Where the learned controllers in use come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SetSource {
    Shipped,
    TrainedHere,
    Loaded,
}

/// A hand-tuned fish swimming between the buoys: the bridge (`body/motor_bridge.rs`)
/// turns "swim to the buoy at full speed" into swim-MC and turn-MC commands.
#[derive(Clone, Debug)]
struct HandTunedTracker {
    fish: PhysicalFish,
    buoys_m: [Vec3; 2],
    next: usize,
    reached_secs: Vec<f32>,
    time_secs: f32,
}

impl HandTunedTracker {
    fn step(&mut self) {
        let here = self.fish.point.position_m;
        let wish = (self.buoys_m[self.next] - here).normalize_or(self.fish.heading())
            * self.fish.top_speed_m_per_s();
        let intent = self.fish.plan(wish);
        self.fish.step(&intent, Vec3::ZERO);
        self.time_secs += self.fish.body().dt_secs();
        let reach = self.fish.body_length_m();
        let flat = |v: Vec3| Vec3::new(v.x, 0.0, v.z);
        if flat(self.buoys_m[self.next] - self.fish.point.position_m).length() < reach {
            self.reached_secs.push(self.time_secs);
            self.next = 1 - self.next;
        }
    }
}

#[derive(Clone, Debug)]
enum Demo {
    Learned(Box<BuoyTracker>),
    HandTuned(Box<HandTunedTracker>),
}

/// Why the race cannot start yet: the sharks it races are snapshotted during the
/// first drill.
#[derive(Clone, Debug, PartialEq)]
pub struct RaceNotReady {
    pub done: u64,
    pub needed: u64,
}

impl std::fmt::Display for RaceNotReady {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&crate::tr!(
            "learning-race-not-ready",
            done = self.done,
            needed = self.needed
        ))
    }
}

impl std::error::Error for RaceNotReady {}

/// The learning lab.
#[derive(Clone, Debug)]
pub struct LearningLab {
    species: BodySpecies,
    seed: u64,
    annealing_steps: u64,
    drills: Vec<Task>,
    /// The drill being trained (index into `drills`), `drills.len()` when done.
    drill: usize,
    trainer: Trainer,
    finished: Vec<TrainedDrill>,
    /// The abstraction of each finished drill (for the plots).
    abstractions: Vec<Abstraction>,
    trained_set: Option<LearnedControllerSet>,
    loaded_set: Option<LearnedControllerSet>,
    /// The first drill's snapshots for the race.
    race_entrants: Vec<RaceEntrant>,
    race: Option<Race>,
    controller: ControllerChoice,
    demo: Demo,
    /// Where the demo's body frame origin sits in the tank (metres).
    origin_m: Vec3,
    demo_steps: u64,
    /// The open-water tank the demo fish and the race swim in.
    tank: Tank,
}

/// The buoys of Fig. 9 in body lengths from the demo fish's start (forward, left):
/// a far one ahead, then a near one beside the start.
const BUOYS_BODY_LENGTHS: [[f32; 2]; 2] = [[8.0, 2.0], [1.0, 4.0]];

impl LearningLab {
    /// A lab for `species` training each drill for `annealing_steps` evaluations
    /// from seed `seed`.
    pub fn new(
        species: BodySpecies,
        annealing_steps: u64,
        seed: u64,
        controller: ControllerChoice,
        tank: &Tank,
    ) -> Self {
        let drills = routine_drills();
        let trainer = Self::trainer_for(species, drills[0], annealing_steps, seed, true);
        let origin_m = tank.center_m() + Vec3::new(-2.5, 0.0, 1.5);
        let mut lab = Self {
            species,
            seed,
            annealing_steps: annealing_steps.max(1),
            drills,
            drill: 0,
            trainer,
            finished: Vec::new(),
            abstractions: Vec::new(),
            trained_set: None,
            loaded_set: None,
            race_entrants: Vec::new(),
            race: None,
            controller,
            demo: Demo::HandTuned(Box::new(HandTunedTracker {
                fish: PhysicalFish::new(species, species.body_length_m(), origin_m, Vec3::X, 0.1),
                buoys_m: [Vec3::ZERO; 2],
                next: 0,
                reached_secs: Vec::new(),
                time_secs: 0.0,
            })),
            origin_m,
            demo_steps: 0,
            tank: *tank,
        };
        lab.rebuild_demo();
        lab
    }

    fn trainer_for(
        species: BodySpecies,
        task: Task,
        steps: u64,
        seed: u64,
        checkpoints: bool,
    ) -> Trainer {
        let schedule = AnnealingSchedule {
            planned_evaluations: steps.max(1),
            ..AnnealingSchedule::default()
        };
        let mut trainer = Trainer::new(
            TrainingSetup {
                species,
                task,
                ..TrainingSetup::default()
            },
            schedule,
            seed,
        );
        if checkpoints {
            // The paper's race: 90 … 6840 steps, scaled to this training length.
            let scale = steps as f64 / *PAPER_RACE_STEPS.last().unwrap_or(&6840) as f64;
            let counts: Vec<u64> = PAPER_RACE_STEPS
                .iter()
                .map(|&k| ((k as f64 * scale).round() as u64).clamp(1, steps.max(1)))
                .collect();
            trainer.set_checkpoints(&counts);
        }
        trainer
    }

    pub fn species(&self) -> BodySpecies {
        self.species
    }
    pub fn seed(&self) -> u64 {
        self.seed
    }
    /// The open-water tank the demo fish and the race swim in.
    pub fn tank(&self) -> &Tank {
        &self.tank
    }
    /// Length of one step of the demo fish and the race, seconds (the fish
    /// world's one step).
    pub fn dt_secs(&self) -> f32 {
        crate::sim::common::paper_time::FISH_STEP_SECS
    }
    /// Body steps the demo fish has swum since it (re)started.
    pub fn demo_steps(&self) -> u64 {
        self.demo_steps
    }
    pub fn drills(&self) -> &[Task] {
        &self.drills
    }
    /// The drill in training (`None` once all are learned).
    pub fn current_drill(&self) -> Option<usize> {
        (self.drill < self.drills.len()).then_some(self.drill)
    }
    pub fn trainer(&self) -> &Trainer {
        &self.trainer
    }
    pub fn finished_drills(&self) -> &[TrainedDrill] {
        &self.finished
    }
    /// The abstraction of finished drill `k`.
    pub fn abstraction(&self, k: usize) -> Option<&Abstraction> {
        self.abstractions.get(k)
    }
    /// The abstraction of what the current drill has learned so far.
    pub fn current_abstraction(&self) -> Abstraction {
        abstract_controls(
            self.trainer.best_controls(),
            &AbstractionSettings::default(),
        )
    }
    pub fn annealing_steps(&self) -> u64 {
        self.annealing_steps
    }
    /// Share of the whole training done, 0–1.
    pub fn progress(&self) -> f32 {
        let n = self.drills.len() as f32;
        if self.drill >= self.drills.len() {
            return 1.0;
        }
        (self.drill as f32 + self.trainer.progress()) / n
    }
    pub fn controller(&self) -> ControllerChoice {
        self.controller
    }
    pub fn race(&self) -> Option<&Race> {
        self.race.as_ref()
    }
    /// Entrants available for a race (after the first drill's checkpoints).
    pub fn race_entrants(&self) -> &[RaceEntrant] {
        &self.race_entrants
    }

    /// The learned controllers in use and where they come from.
    pub fn learned_set(&self) -> (LearnedControllerSet, SetSource) {
        if let Some(set) = &self.loaded_set {
            return (set.clone(), SetSource::Loaded);
        }
        if let Some(set) = &self.trained_set {
            return (set.clone(), SetSource::TrainedHere);
        }
        match LearnedControllerSet::pretrained() {
            Ok(set) => (set, SetSource::Shipped),
            // The shipped file is checked by the tests; an empty set is the
            // fallback that keeps the app running.
            Err(_) => (
                LearnedControllerSet::new(self.species, Vec::new()),
                SetSource::Shipped,
            ),
        }
    }

    /// Runs up to `n` annealing evaluations (moving on to the next drill when one
    /// is done); returns how many ran.
    pub fn train(&mut self, n: usize) -> usize {
        let mut done = 0;
        while done < n && self.drill < self.drills.len() {
            let left = self
                .annealing_steps
                .saturating_sub(self.trainer.evaluations())
                .min((n - done) as u64) as usize;
            done += self.trainer.run_evaluations(left);
            if self.trainer.is_finished() {
                self.finish_drill();
            } else {
                break;
            }
        }
        done
    }

    fn finish_drill(&mut self) {
        let settings = AbstractionSettings::default();
        if self.drill == 0 {
            self.race_entrants = RaceEntrant::from_checkpoints(self.trainer.checkpoints());
        }
        self.abstractions
            .push(abstract_controls(self.trainer.best_controls(), &settings));
        self.finished
            .push(TrainedDrill::from_trainer(&self.trainer, &settings));
        self.drill += 1;
        if let Some(&task) = self.drills.get(self.drill) {
            self.trainer = Self::trainer_for(
                self.species,
                task,
                self.annealing_steps,
                self.seed + self.drill as u64,
                false,
            );
        } else {
            self.trained_set = Some(LearnedControllerSet::new(
                self.species,
                self.finished.clone(),
            ));
            if self.controller == ControllerChoice::Learned && self.loaded_set.is_none() {
                self.rebuild_demo();
            }
        }
    }

    /// Switches the demo fish's controllers (it starts again at the start).
    pub fn set_controller(&mut self, controller: ControllerChoice) {
        self.controller = controller;
        self.rebuild_demo();
    }

    /// Loads a learned set from JSON; on success the demo uses it.
    pub fn load_json(&mut self, text: &str) -> Result<(), LearnedSetError> {
        let set = LearnedControllerSet::from_json(text)?;
        set.motor_map()?;
        self.loaded_set = Some(set);
        self.rebuild_demo();
        Ok(())
    }

    /// The set in use as JSON, for saving.
    pub fn save_json(&self) -> Result<String, LearnedSetError> {
        self.learned_set().0.to_json()
    }

    /// Starts the race of the sharks snapshotted during the first drill.
    pub fn start_race(&mut self) -> Result<(), RaceNotReady> {
        if self.race_entrants.is_empty() {
            return Err(RaceNotReady {
                done: if self.drill == 0 {
                    self.trainer.evaluations()
                } else {
                    self.annealing_steps
                },
                needed: self.annealing_steps,
            });
        }
        self.race = Some(Race::new(
            self.race_entrants.clone(),
            self.species,
            BodyParams::default(),
        ));
        Ok(())
    }

    /// Where the race's body frame origin sits in the tank.
    pub fn race_origin_m(&self) -> Vec3 {
        self.origin_m + Vec3::new(-1.0, 0.0, 0.0)
    }

    fn rebuild_demo(&mut self) {
        self.demo_steps = 0;
        let l = self.species.body_length_m();
        let buoys_body = BUOYS_BODY_LENGTHS.map(|[f, left]| Vec3::new(f * l, left * l, 0.0));
        let buoys_tank = buoys_body.map(|b| self.origin_m + to_tank_frame(b));
        self.demo = match self.controller {
            ControllerChoice::Learned => match self.learned_set().0.motor_map() {
                Ok(map) => Demo::Learned(Box::new(BuoyTracker::new(
                    map,
                    self.species,
                    BodyParams::default(),
                    buoys_body,
                ))),
                Err(_) => self.hand_tuned(buoys_tank),
            },
            ControllerChoice::HandTuned => self.hand_tuned(buoys_tank),
        };
    }

    fn hand_tuned(&self, buoys_tank: [Vec3; 2]) -> Demo {
        Demo::HandTuned(Box::new(HandTunedTracker {
            fish: PhysicalFish::new(
                self.species,
                self.species.body_length_m(),
                self.origin_m,
                Vec3::X,
                0.1,
            ),
            buoys_m: buoys_tank,
            next: 0,
            reached_secs: Vec::new(),
            time_secs: 0.0,
        }))
    }

    /// One body step of the demo fish and of the race.
    pub fn step(&mut self) {
        self.demo_steps += 1;
        match &mut self.demo {
            Demo::Learned(t) => t.step(),
            Demo::HandTuned(t) => t.step(),
        }
        if let Some(race) = &mut self.race {
            race.step();
        }
    }

    /// The demo fish's nodes in the tank frame.
    pub fn demo_nodes_m(&self) -> [Vec3; NODE_COUNT] {
        match &self.demo {
            Demo::Learned(t) => t
                .body()
                .positions_m()
                .map(|p| self.origin_m + to_tank_frame(p)),
            Demo::HandTuned(t) => t.fish.nodes_m(),
        }
    }

    /// The buoys in the tank frame.
    pub fn buoys_m(&self) -> [Vec3; 2] {
        match &self.demo {
            Demo::Learned(t) => t.buoys_m().map(|b| self.origin_m + to_tank_frame(b)),
            Demo::HandTuned(t) => t.buoys_m,
        }
    }

    /// Seconds at which the demo fish reached a buoy.
    pub fn buoy_times_secs(&self) -> Vec<f32> {
        match &self.demo {
            Demo::Learned(t) => t.reached_secs().to_vec(),
            Demo::HandTuned(t) => t.reached_secs.clone(),
        }
    }

    /// Each racing shark's nodes in the tank frame, with its annealing steps.
    pub fn race_nodes_m(&self) -> Vec<(u64, [Vec3; NODE_COUNT])> {
        let origin = self.race_origin_m();
        self.race
            .iter()
            .flat_map(|race| {
                race.entrants()
                    .zip(race.bodies())
                    .map(|(e, b)| {
                        (
                            e.annealing_steps,
                            b.positions_m().map(|p| origin + to_tank_frame(p)),
                        )
                    })
                    .collect::<Vec<_>>()
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::learning::learning_lab::*;

    fn lab(steps: u64) -> LearningLab {
        LearningLab::new(
            BodySpecies::Fish,
            steps,
            1,
            ControllerChoice::Learned,
            &Tank::default(),
        )
    }

    #[test]
    fn training_walks_through_every_drill_and_builds_a_set() {
        let mut l = lab(12);
        assert_eq!(l.current_drill(), Some(0));
        assert_eq!(l.learned_set().1, SetSource::Shipped);
        assert!(l.start_race().is_err(), "no race before the first drill");
        let mut spent = 0;
        while l.current_drill().is_some() {
            spent += l.train(5);
            assert!(spent < 1000);
        }
        assert_eq!(spent, 12 * l.drills().len());
        assert_eq!(l.finished_drills().len(), l.drills().len());
        assert_eq!(l.progress(), 1.0);
        assert_eq!(l.learned_set().1, SetSource::TrainedHere);
        assert_eq!(l.race_entrants().len(), PAPER_RACE_STEPS.len());
        l.start_race().unwrap();
        for _ in 0..10 {
            l.step();
        }
        let race = l.race_nodes_m();
        assert_eq!(race.len(), PAPER_RACE_STEPS.len());
        assert!(
            race.iter()
                .all(|(_, nodes)| nodes.iter().all(|p| p.is_finite()))
        );
    }

    #[test]
    fn both_controllers_swim_the_demo_fish_and_a_bad_file_changes_nothing() {
        for choice in [ControllerChoice::Learned, ControllerChoice::HandTuned] {
            let mut l = lab(4);
            l.set_controller(choice);
            let start = l.demo_nodes_m()[0];
            for _ in 0..200 {
                l.step();
            }
            let moved = l.demo_nodes_m()[0].distance(start);
            assert!(moved > 0.3, "{choice:?} moved {moved} m in 11 s");
            let tank = Tank::default();
            assert!(l.buoys_m().iter().all(|b| tank.contains(*b, 0.5)));
        }
        let mut l = lab(4);
        let saved = l.save_json().unwrap();
        assert!(l.load_json("{ not json").is_err());
        assert!(
            l.load_json(&saved.replace("\"version\": 1", "\"version\": 9"))
                .is_err()
        );
        assert_eq!(l.learned_set().1, SetSource::Shipped);
        l.load_json(&saved).unwrap();
        assert_eq!(l.learned_set().1, SetSource::Loaded);
    }
}
