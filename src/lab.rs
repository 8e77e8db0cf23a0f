//! The running experiment: the simulated world, the teacher's settings and the clock
//! that advances one in fixed steps.
//!
//! `Lab` has no GPU and no UI, so everything the UI and the automation API can do to
//! a run is tested natively. The app owns one `Lab` and draws it.

use glam::Vec3;

use crate::clock::{FixedStepClock, RateMeter};
use crate::i18n::{arg, tr};
use crate::settings::physics::TURN_MAX_DEG;
use crate::settings::{Settings, Side};
use crate::sim::World;
use crate::sim::learning::learning_lab::LearningLab;
use crate::sim::learning::learning_lab::RaceNotReady;
use crate::sim::scene::SceneWorld;
use crate::tr;

#[cfg(not(target_arch = "wasm32"))]
pub(crate) mod census;
mod run;
mod skip;
pub use run::{BODY_TRACE_SECS, BodySample, Run};
pub use skip::{SKIP_FRAME_BUDGET_SECS, SKIP_LIMIT_SECS, SkipOutcome, SkipProgress};

/// Why the lab refused a command (`shoal.turn`, `shoal.train`, `shoal.race`).
/// In the language in force: English unless the page asks for another.
#[derive(Clone, Debug, PartialEq)]
pub enum LabError {
    /// The command (named without its parentheses) needs the learning lab.
    LearningLabOnly(&'static str),
    PhysicsSceneOnly,
    NoFishSelected,
    TurnOutOfRange(f32),
    RaceNotReady(RaceNotReady),
    NoMoment,
}

impl From<RaceNotReady> for LabError {
    fn from(e: RaceNotReady) -> Self {
        Self::RaceNotReady(e)
    }
}

impl std::fmt::Display for LabError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let text = match self {
            Self::LearningLabOnly(command) => {
                tr!("lab-error-learning-lab-only", command = *command)
            }
            Self::PhysicsSceneOnly => tr("lab-error-physics-scene-only"),
            Self::NoFishSelected => tr("lab-error-no-fish-selected"),
            Self::TurnOutOfRange(angle) => tr!(
                "lab-error-turn-out-of-range",
                // NaN and infinity as Rust writes them, not as symbols.
                angle = if angle.is_finite() {
                    arg(*angle)
                } else {
                    arg(angle.to_string())
                },
                max = TURN_MAX_DEG
            ),
            Self::RaceNotReady(e) => return std::fmt::Display::fmt(e, f),
            Self::NoMoment => tr("lab-error-no-moment"),
        };
        f.write_str(&text)
    }
}

impl std::error::Error for LabError {}

/// The running experiment: one tank, or two side by side, sharing one clock.
pub struct Lab {
    settings: Settings,
    clock: FixedStepClock,
    /// The left tank, then the right one while comparing.
    runs: Vec<Run>,
    steps_meter: RateMeter,
    /// Counts rebuilds, so each rebuilt world gets a new generation number.
    rebuilds: u64,
    /// Wall-clock seconds of simulation a frame may spend (`None`: no limit).
    frame_budget_secs: Option<f64>,
    /// Smoothed wall-clock cost of one step of every tank, seconds.
    step_cost_secs: f64,
    /// The learning lab while another scene is shown.
    parked_learning: Option<LearningLab>,
    /// Smoothed wall-clock cost of one annealing evaluation, seconds.
    evaluation_cost_secs: f64,
    /// *Skip to the moment* under way, and how the last one ended.
    skip: Option<skip::Skip>,
    skip_outcome: Option<SkipOutcome>,
    skips_finished: u64,
}

/// Share of the frame budget that training may use in the learning scene (0.5:
/// the rest draws the demo fish and the plots).
const TRAINING_SHARE_OF_BUDGET: f64 = 0.5;

/// The frame budget the app uses, seconds. Default 0.025 s: with drawing and the
/// UI a frame stays near 30 frames/s or better, so the camera and sliders stay
/// responsive however many fish swim; the simulation slows down instead
/// ("slowed down" in the status line).
pub const INTERACTIVE_FRAME_BUDGET_SECS: f64 = 0.025;

impl Lab {
    pub fn new(settings: Settings) -> Self {
        let mut settings = settings;
        settings.clamp();
        let mut lab = Self {
            settings,
            clock: FixedStepClock::new(f64::from(World::DT_SECS)),
            runs: Vec::new(),
            steps_meter: RateMeter::default(),
            rebuilds: 0,
            frame_budget_secs: None,
            step_cost_secs: 0.0,
            parked_learning: None,
            evaluation_cost_secs: 0.0,
            skip: None,
            skip_outcome: None,
            skips_finished: 0,
        };
        lab.rebuild();
        lab
    }

    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The left (or only) tank's world.
    pub fn scene(&self) -> &SceneWorld {
        &self.runs[0].scene
    }

    /// The left (or only) tank's learning lab, for the app's actions (race,
    /// save, load) and training.
    pub fn learning_mut(&mut self) -> Option<&mut LearningLab> {
        self.runs[0].scene.learning_mut()
    }

    /// The tanks shown: one, or two while comparing.
    pub fn runs(&self) -> &[Run] {
        &self.runs
    }

    /// The run of `side`, if shown.
    pub fn run(&self, side: Side) -> Option<&Run> {
        self.runs.get(side.index())
    }

    /// Changes whenever the left world is rebuilt.
    pub fn world_generation(&self) -> u64 {
        self.runs[0].generation()
    }

    /// Does this scene show two tanks?
    pub fn comparing(&self) -> bool {
        self.wanted_runs() == 2
    }

    /// Replaces the settings, doing what each change means: a new seed, scene or
    /// layout (compare on or off) rebuilds the worlds so both tanks start from the
    /// same positions; new counts add or remove fish; sliders take effect at the
    /// next step. Out-of-range values are clamped, so no path can put the world in
    /// a state the UI could not.
    pub fn apply_settings(&mut self, new: Settings) {
        let mut new = new;
        new.settle(&self.settings);
        new.clamp();
        let before = std::mem::replace(&mut self.settings, new);
        let controller = self.settings.learning.controller;
        if before.learning.controller != controller
            && let Some(l) = self.learning_mut()
        {
            l.set_controller(controller);
        }
        let rebuild = before.seed != self.settings.seed
            || before.scene != self.settings.scene
            || self
                .settings
                .scene
                .class()
                .needs_rebuild(&before, &self.settings)
            || self.runs.len() != self.wanted_runs();
        let unpaused = before.paused && !self.settings.paused;
        if self.skip.is_some() && (rebuild || !skip::skip_survives(&before, &self.settings)) {
            self.skip = None;
        }
        if rebuild {
            self.rebuild();
        } else {
            for run in &mut self.runs {
                run.follow(&self.settings);
            }
        }
        if unpaused {
            self.clock.clear();
        }
    }

    fn wanted_runs(&self) -> usize {
        self.settings.scene.class().tanks(&self.settings)
    }

    fn rebuild(&mut self) {
        self.skip = None;
        self.skip_outcome = None;
        let mut learning = self.parked_learning.take();
        for run in std::mem::take(&mut self.runs) {
            if let Some(l) = run.scene.into_learning() {
                learning = Some(l);
            }
        }
        self.runs = Side::BOTH[..self.wanted_runs()]
            .iter()
            .map(|&side| {
                self.rebuilds += 1;
                Run::new(side, &self.settings, self.rebuilds, &mut learning)
            })
            .collect();
        // A learning lab the scene did not take waits for the next visit.
        self.parked_learning = learning;
        let max_steps = self.clock.max_steps_per_frame;
        self.clock = FixedStepClock::new(self.runs[0].scene.dt_secs());
        self.clock.max_steps_per_frame = max_steps;
        self.step_cost_secs = 0.0;
        self.clock.clear();
    }

    /// Runs `n` annealing evaluations of the learning lab now (`shoal.train(n)`).
    pub fn train(&mut self, n: u32) -> Result<u32, LabError> {
        let Some(l) = self.learning_mut() else {
            return Err(LabError::LearningLabOnly("train"));
        };
        Ok(l.train(n as usize) as u32)
    }

    /// Starts the learning lab's training again from a brain-dead fish.
    pub fn reset_training(&mut self) {
        if self.learning_mut().is_some() {
            self.parked_learning = None;
            self.runs.clear();
            self.rebuild();
        }
    }

    /// Trains for a share of the frame budget while `learning.training` is on,
    /// whether or not the simulation is paused: training has its own Start and
    /// Pause button, and pausing the swimmer must not stop it silently (it did:
    /// the button said "Pause training" and `state().learning.evaluations`
    /// stayed 0 in a paused page).
    fn train_for_frame(&mut self) {
        if !self.settings.learning.training {
            return;
        }
        let budget = self.frame_budget_secs.unwrap_or(0.02) * TRAINING_SHARE_OF_BUDGET;
        let n = if self.evaluation_cost_secs > 0.0 {
            ((budget / self.evaluation_cost_secs).floor() as usize).clamp(1, 200)
        } else {
            1
        };
        let Some(l) = self.learning_mut() else {
            return;
        };
        let started = web_time::Instant::now();
        let done = l.train(n);
        if done > 0 {
            let cost = started.elapsed().as_secs_f64() / done as f64;
            self.evaluation_cost_secs = if self.evaluation_cost_secs > 0.0 {
                0.8 * self.evaluation_cost_secs + 0.2 * cost
            } else {
                cost
            };
        }
    }

    /// Rebuilds the worlds from `seed` (or the current seed), keeping every other
    /// setting.
    pub fn reset(&mut self, seed: Option<u64>) {
        if let Some(seed) = seed {
            self.settings.seed = seed.min(crate::settings::SEED_MAX);
        }
        self.rebuild();
    }

    /// Wall seconds one step of every tank took lately (0 before any was
    /// measured): the experiment panel scales its time estimate by it.
    pub fn step_cost_secs(&self) -> f64 {
        self.step_cost_secs
    }

    /// Limits the simulation's wall-clock time per frame (the app sets
    /// [`INTERACTIVE_FRAME_BUDGET_SECS`]); steps per frame then adapt to the measured
    /// cost of a step. Results stay deterministic: only how many fixed steps run per
    /// frame changes, never their length.
    pub fn set_frame_budget(&mut self, budget_secs: Option<f64>) {
        self.frame_budget_secs = budget_secs;
    }

    /// Runs the steps owed for a frame of `frame_secs` real seconds (none while
    /// paused). `now_secs` is wall-clock time, for the steps-per-second meter.
    pub fn advance_frame(&mut self, frame_secs: f64, now_secs: f64) -> u32 {
        /// Steps per frame without a budget, or before a step's cost is known
        /// (see [`FixedStepClock`]).
        const MAX_STEPS: u32 = 32;
        // With a budget and a known cost, the budget alone limits a frame: up to
        // every step the longest counted frame owes at the top speed. On a
        // computer whose drawing is slow (a weak GPU at 5 frames/s) a cheap
        // scene then still runs at 8×; a fixed 32 steps a frame held it at 2.7×
        // however little the steps cost.
        let most_owed = (crate::clock::MAX_FRAME_SECS * f64::from(crate::settings::SPEED_MAX)
            / self.step_secs())
        .ceil() as u32;
        self.clock.max_steps_per_frame = match self.frame_budget_secs {
            Some(budget) if self.step_cost_secs > 0.0 => {
                ((budget / self.step_cost_secs).floor() as u32).clamp(1, most_owed.max(MAX_STEPS))
            }
            _ => MAX_STEPS,
        };
        if self.skip.is_some() {
            // Looking ahead: as many steps as fit in the skip's budget, paused
            // or not (the user asked for it).
            let before = self.runs[0].scene.steps();
            self.advance_skip(SKIP_FRAME_BUDGET_SECS);
            let steps = self.runs[0].scene.steps().saturating_sub(before) as u32;
            self.steps_meter.record(now_secs, u64::from(steps));
            return steps;
        }
        let steps = if self.settings.paused {
            0
        } else {
            self.clock
                .steps_for_frame(frame_secs, f64::from(self.settings.speed))
        };
        self.train_for_frame();
        let started = web_time::Instant::now();
        self.run_steps(steps);
        if steps > 0 {
            let cost = started.elapsed().as_secs_f64() / f64::from(steps);
            // Smoothed over a few frames as it falls; the first measurement, and
            // any rise (a slider that added thousands of fish), taken as is, so
            // that the next frame does not plan on the old, cheaper steps.
            self.step_cost_secs = if self.step_cost_secs > 0.0 && cost < self.step_cost_secs {
                0.8 * self.step_cost_secs + 0.2 * cost
            } else {
                cost
            };
        }
        self.steps_meter.record(now_secs, u64::from(steps));
        steps
    }

    /// Starts a turn of `angle_deg` degrees (+ left) on the selected physical fish.
    pub fn turn_selected(&mut self, angle_deg: f32) -> Result<(), LabError> {
        if !self.runs[0].scene.turns_on_command() {
            return Err(LabError::PhysicsSceneOnly);
        }
        let class = self.settings.scene.class();
        let Some(selected) = class.selected(&self.settings, Side::Left) else {
            return Err(LabError::NoFishSelected);
        };
        if !angle_deg.is_finite() || angle_deg.abs() > TURN_MAX_DEG {
            return Err(LabError::TurnOutOfRange(angle_deg));
        }
        self.runs[0].scene.turn(selected as usize, angle_deg);
        Ok(())
    }

    /// Length of one simulation step of the current scene, seconds.
    pub fn step_secs(&self) -> f64 {
        self.runs[0].scene.dt_secs()
    }

    /// Runs exactly `n` steps now, paused or not (single step, `shoal.step(n)`).
    pub fn step(&mut self, n: u32) {
        self.run_steps(n);
    }

    fn run_steps(&mut self, n: u32) {
        for run in &mut self.runs {
            for i in 0..n {
                run.step(i + 1 == n);
            }
        }
    }

    /// How far between the last two simulated states to draw (0 while paused).
    pub fn draw_alpha(&self) -> f32 {
        if self.settings.paused {
            1.0
        } else {
            self.clock.alpha()
        }
    }

    /// Where fish `index` of the left tank should be drawn.
    pub fn drawn_position_m(&self, index: usize) -> Vec3 {
        self.runs[0].drawn_position_m(index, self.draw_alpha())
    }

    /// Simulation steps per second of wall-clock time over the last second.
    pub fn steps_per_sec(&self) -> f64 {
        self.steps_meter.rate_per_sec()
    }

    /// Has the clock been behind for more than a moment (the machine cannot
    /// keep up)?
    pub fn slowed_down(&self) -> bool {
        self.clock.slowed_down()
    }

    /// Did the last frame hit the step cap?
    pub fn fell_behind(&self) -> bool {
        self.clock.fell_behind()
    }

    /// The metrics history of every tank shown as one CSV text.
    pub fn metrics_csv(&self) -> String {
        let mut csv = crate::metrics_history::CSV_HEADER.to_owned();
        for run in &self.runs {
            run.history.to_csv(run.side.name(), &mut csv);
        }
        csv
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::Scene;

    #[test]
    fn every_scene_draws_its_animals_between_their_last_two_states() {
        for scene in Scene::ALL {
            let mut settings = Settings {
                scene,
                ..Settings::default()
            };
            settings.left.sharks = 1;
            settings.left.stingrays = 1;
            let mut lab = Lab::new(settings);
            lab.step(3);
            let run = &lab.runs()[0];
            let (mut before, mut now) = (Vec::new(), Vec::new());
            run.scene().positions_m(&mut now);
            before.clone_from(&run.previous_positions_m);
            assert_eq!(now.len(), run.scene().animal_count(), "{scene:?}");
            assert!(now != before, "{scene:?}: nobody moved");
            assert_eq!(run.drawn_positions_m(0.0), before, "{scene:?}");
            assert_eq!(run.drawn_positions_m(1.0), now, "{scene:?}");
            let half = run.drawn_positions_m(0.5);
            for (k, p) in half.iter().enumerate() {
                assert!(p.distance(before[k].lerp(now[k], 0.5)) < 1e-5, "{scene:?}");
            }
            // Muscle bodies draw their nodes the same way.
            let (mut nodes_before, mut nodes_now) = (Vec::new(), Vec::new());
            run.scene().nodes_m(&mut nodes_now);
            nodes_before.clone_from(&run.previous_nodes_m);
            assert_eq!(run.drawn_nodes_all_m(0.0), nodes_before, "{scene:?}");
            assert_eq!(run.drawn_nodes_all_m(1.0), nodes_now, "{scene:?}");
            let bodies = run.scene().bodies_to_draw();
            let muscles = matches!(scene, Scene::Physics | Scene::Reef | Scene::Learning);
            assert_eq!(!bodies.is_empty(), muscles, "{scene:?}");
        }
    }

    fn positions(lab: &Lab) -> Vec<Vec3> {
        lab.scene()
            .boids()
            .unwrap()
            .fish()
            .iter()
            .map(|f| f.position_m)
            .collect()
    }

    #[test]
    fn paused_lab_does_not_advance_but_single_step_does() {
        let mut lab = Lab::new(Settings {
            paused: true,
            ..Settings::default()
        });
        assert_eq!(lab.advance_frame(0.1, 0.1), 0);
        assert_eq!(lab.scene().boids().unwrap().steps(), 0);
        lab.step(3);
        assert_eq!(lab.scene().boids().unwrap().steps(), 3);
    }

    #[test]
    fn changing_the_seed_rebuilds_and_the_same_seed_repeats_the_run() {
        let mut a = Lab::new(Settings::default());
        let mut b = Lab::new(Settings::default());
        a.step(120);
        b.step(120);
        assert_eq!(positions(&a), positions(&b));
        b.apply_settings(Settings {
            seed: 99,
            ..b.settings().clone()
        });
        assert_eq!(
            b.scene().boids().unwrap().steps(),
            0,
            "a new seed starts a new run"
        );
        b.step(120);
        assert_ne!(positions(&a), positions(&b));
        b.reset(Some(1));
        b.step(120);
        assert_eq!(positions(&a), positions(&b));
    }

    #[test]
    fn changing_the_fish_count_keeps_the_run_going() {
        let mut lab = Lab::new(Settings::default());
        lab.step(10);
        let mut settings = lab.settings().clone();
        settings.left.fish_count = 37;
        lab.apply_settings(settings);
        assert_eq!(lab.scene().boids().unwrap().fish().len(), 37);
        assert_eq!(lab.scene().boids().unwrap().steps(), 10);
    }

    #[test]
    fn slow_frames_still_run_a_cheap_scene_at_top_speed() {
        // A weak GPU: 5 frames a second. Ten fish cost microseconds a step, so
        // the interactive budget lets every owed step run: 8× real time. Without
        // a budget the clock's fixed 32 steps a frame hold it at 2.7×.
        let settings = |lab: &Lab| {
            let mut s = lab.settings().clone();
            s.speed = 8.0;
            s.left.fish_count = 10;
            s
        };
        let mut budgeted = Lab::new(Settings::default());
        budgeted.set_frame_budget(Some(INTERACTIVE_FRAME_BUDGET_SECS));
        budgeted.apply_settings(settings(&budgeted));
        let mut fixed = Lab::new(Settings::default());
        fixed.apply_settings(settings(&fixed));
        for frame in 0..10 {
            let now = f64::from(frame) * 0.2;
            budgeted.advance_frame(0.2, now);
            fixed.advance_frame(0.2, now);
        }
        let steps = |lab: &Lab| lab.scene().boids().unwrap().steps();
        // Each 0.2 s frame owes 96 steps of 1/60 s at 8×; the first frame,
        // before a step's cost is known, runs 32: at most 32 + 9 × 96 = 896.
        assert!(
            (850..=896).contains(&steps(&budgeted)),
            "{}",
            steps(&budgeted)
        );
        assert_eq!(steps(&fixed), 320);
        assert!(!budgeted.slowed_down() && fixed.slowed_down());
    }

    #[test]
    fn speed_multiplies_the_steps_per_frame() {
        let mut slow = Lab::new(Settings {
            speed: 0.25,
            ..Settings::default()
        });
        let mut fast = Lab::new(Settings {
            speed: 8.0,
            ..Settings::default()
        });
        for frame in 0..60 {
            let now = f64::from(frame) / 60.0;
            slow.advance_frame(1.0 / 60.0, now);
            fast.advance_frame(1.0 / 60.0, now);
        }
        assert!(
            (14..=15).contains(&slow.scene().boids().unwrap().steps()),
            "{}",
            slow.scene().boids().unwrap().steps()
        );
        assert!(
            (479..=480).contains(&fast.scene().boids().unwrap().steps()),
            "{}",
            fast.scene().boids().unwrap().steps()
        );
    }

    #[test]
    fn drawn_positions_lie_between_the_last_two_states() {
        let mut lab = Lab::new(Settings::default());
        lab.advance_frame(1.5 / 60.0, 0.0);
        let alpha = lab.clock.alpha();
        assert!(alpha > 0.0 && alpha < 1.0);
        for (i, fish) in lab.scene().boids().unwrap().fish().iter().enumerate() {
            let drawn = lab.drawn_position_m(i);
            let previous = lab.runs[0].previous_positions_m[i];
            let total = previous.distance(fish.position_m);
            assert!(drawn.distance(previous) <= total + 1e-5);
            assert!(drawn.distance(fish.position_m) <= total + 1e-5);
        }
    }

    fn physics_lab() -> Lab {
        let mut settings = Settings {
            scene: Scene::Physics,
            ..Settings::default()
        };
        settings.physics.fish_count = 4;
        settings.physics.sharks = 1;
        Lab::new(settings)
    }

    #[test]
    fn the_physics_scene_steps_muscle_fish_at_the_body_step_and_follows_its_settings() {
        let mut lab = physics_lab();
        let run = &lab.runs()[0];
        assert_eq!(run.scene().physics().unwrap().animals().len(), 5);
        assert!(
            lab.scene().boids().is_none(),
            "no boids in the physics tank"
        );
        assert!(
            !lab.scene().obstacles().is_empty(),
            "the seed's rocks are there"
        );
        lab.advance_frame(0.2, 0.2);
        let steps = lab.runs()[0].steps();
        assert!(
            (3..=4).contains(&steps),
            "0.2 s at 0.055 s per step: {steps}"
        );
        assert!((lab.runs()[0].time_secs() - steps as f64 * 0.055).abs() < 1e-4);

        let mut settings = lab.settings().clone();
        settings.physics.fish_count = 6;
        settings.physics.selected = Some(2);
        settings.physics.hand_control = true;
        settings.physics.hand_speed = 1.0;
        lab.apply_settings(settings);
        assert_eq!(lab.runs()[0].steps(), steps, "more fish, same run");
        let physics = lab.runs()[0].scene().physics().unwrap();
        assert_eq!((physics.fish_count(), physics.shark_count()), (6, 1));
        lab.step(40);
        let run = &lab.runs()[0];
        let trace = run.body_trace();
        assert_eq!(trace.len(), 40, "the selected fish is traced every step");
        let last = trace.back().unwrap();
        assert!(last.speed_m_per_s > 0.0);
        assert!(last.muscles.iter().any(|&u| u > 0.1), "{:?}", last.muscles);
        // Drawn nodes lie between the last two states.
        let drawn = run.drawn_nodes_m(2, 0.5);
        let now = run.scene().physics().unwrap().animals()[2].nodes_m();
        assert!(drawn.iter().zip(now).all(|(a, b)| a.distance(b) < 0.1));
    }

    #[test]
    fn the_reef_scene_runs_minds_and_rebuilds_only_for_demo_body_and_counts() {
        use crate::sim::reef::demos::ReefScene;
        use crate::sim::reef::world::ReefBodyKind;
        let settings = Settings {
            scene: Scene::Reef,
            ..Settings::default()
        };
        let mut lab = Lab::new(settings);
        let reef = lab.runs()[0].scene().reef().expect("a reef");
        assert_eq!(reef.config().scene, ReefScene::Reef);
        assert_eq!(
            lab.scene().obstacles(),
            reef.obstacles(),
            "the reef's rocks are drawn"
        );
        let animals = reef.animals().len();
        assert_eq!(lab.runs()[0].animal_count(), animals);
        lab.step(20);
        assert_eq!(lab.runs()[0].steps(), 20);
        assert!((lab.step_secs() - 0.055).abs() < 1e-9);
        // Live: visibility, current, selection, minds. Same run.
        let mut s = lab.settings().clone();
        s.reef.visibility_m = 3.0;
        s.reef.selected = Some(0);
        s.reef.traits.predator.digestion_rate_per_unit = Some(0.005);
        lab.apply_settings(s);
        assert_eq!(lab.runs()[0].steps(), 20);
        let reef = lab.runs()[0].scene().reef().unwrap();
        assert_eq!(reef.config().visibility_m, 3.0);
        for a in reef.animals() {
            let ravenous = a.habits.mental.digestion_rate_per_unit == 0.005;
            assert_eq!(
                ravenous,
                a.habits.kind == crate::sim::reef::mind::FishKind::Predator
            );
        }
        lab.step(5);
        assert_eq!(
            lab.runs()[0].body_trace().len(),
            5,
            "muscles of the selected fish"
        );
        assert_eq!(lab.runs()[0].selectable_animals(1.0).len(), animals);
        // A new demo, body or count: a new reef.
        let mut s = lab.settings().clone();
        s.reef.demo = ReefScene::Courtship;
        s.reef.body = ReefBodyKind::PointMass;
        lab.apply_settings(s);
        let reef = lab.runs()[0].scene().reef().unwrap();
        assert_eq!(lab.runs()[0].steps(), 0);
        assert_eq!(reef.animals().len(), 3);
        let mut s = lab.settings().clone();
        s.reef.demo = ReefScene::PredatorAndSchool;
        s.reef.prey_count = Some(30);
        lab.apply_settings(s);
        assert_eq!(lab.runs()[0].scene().reef().unwrap().animals().len(), 31);
        // Drawn positions of point-mass fish lie between the last two states.
        lab.step(3);
        let run = &lab.runs()[0];
        for (i, c, _) in run.selectable_animals(0.5) {
            let now = run.scene().reef().unwrap().animals()[i].body.position_m();
            assert!(c.distance(now) < 0.1);
        }
    }

    #[test]
    fn a_learning_setting_changed_while_another_scene_shows_leaves_that_scene_alone() {
        // The schooling lab runs; a script (or a link) changes the learning
        // lab's training. The fish on show are not started again: the new
        // training waits for the learning lab's next visit.
        let mut lab = Lab::new(Settings::default());
        lab.step(30);
        let generation = lab.world_generation();
        let mut s = lab.settings().clone();
        s.learning.annealing_steps += 10;
        lab.apply_settings(s);
        assert_eq!(lab.world_generation(), generation);
        assert_eq!(lab.runs()[0].steps(), 30);
        // In the learning lab the same change starts a new training.
        let mut s = lab.settings().clone();
        s.scene = Scene::Learning;
        lab.apply_settings(s);
        let annealing = |lab: &Lab| lab.runs()[0].scene().learning().unwrap().annealing_steps();
        assert_eq!(
            annealing(&lab),
            u64::from(lab.settings().learning.annealing_steps)
        );
        let generation = lab.world_generation();
        let mut s = lab.settings().clone();
        s.learning.annealing_steps += 10;
        lab.apply_settings(s);
        assert_ne!(lab.world_generation(), generation);
        assert_eq!(
            annealing(&lab),
            u64::from(lab.settings().learning.annealing_steps)
        );
    }

    #[test]
    fn the_learning_lab_trains_on_request_and_keeps_its_progress_across_scenes() {
        let mut settings = Settings {
            scene: Scene::Learning,
            ..Settings::default()
        };
        settings.learning.annealing_steps = 90;
        let mut lab = Lab::new(settings);
        assert!(lab.scene().boids().is_none() && lab.scene().obstacles().is_empty());
        assert_eq!(lab.train(30), Ok(30));
        lab.step(10);
        assert_eq!(lab.runs()[0].steps(), 10, "the swimmer swims");
        assert!(
            lab.runs()[0]
                .drawn_nodes_m(0, 0.5)
                .iter()
                .all(|p| p.is_finite())
        );
        // To the reef and back: the training is where it was.
        let mut s = lab.settings().clone();
        s.scene = Scene::Reef;
        lab.apply_settings(s);
        assert!(lab.train(1).is_err(), "train() needs the learning lab");
        let mut s = lab.settings().clone();
        s.scene = Scene::Learning;
        lab.apply_settings(s);
        assert_eq!(
            lab.runs()[0]
                .scene()
                .learning()
                .unwrap()
                .trainer()
                .evaluations(),
            30
        );
        // Training runs a little each frame while it is on.
        let mut s = lab.settings().clone();
        s.learning.training = true;
        lab.apply_settings(s);
        lab.advance_frame(0.1, 0.1);
        lab.advance_frame(0.1, 0.2);
        assert!(
            lab.runs()[0]
                .scene()
                .learning()
                .unwrap()
                .trainer()
                .evaluations()
                > 30
        );
        // Settings that change nothing here (the controller, the speed, the
        // boid tank's fish) leave the water open: no aquarium fish, no rocks.
        let mut s = lab.settings().clone();
        s.learning.controller = crate::sim::learning::learning_lab::ControllerChoice::HandTuned;
        s.speed = 2.0;
        s.left.fish_count = 500;
        lab.apply_settings(s);
        assert!(lab.scene().boids().is_none() && lab.scene().obstacles().is_empty());
        // A different length, or Reset training, starts from a brain-dead fish.
        lab.reset_training();
        assert_eq!(
            lab.runs()[0]
                .scene()
                .learning()
                .unwrap()
                .trainer()
                .evaluations(),
            0
        );
        let mut s = lab.settings().clone();
        s.learning.annealing_steps = 120;
        lab.train(5).unwrap();
        lab.apply_settings(s);
        assert_eq!(
            lab.runs()[0].scene().learning().unwrap().annealing_steps(),
            120
        );
        assert_eq!(
            lab.runs()[0]
                .scene()
                .learning()
                .unwrap()
                .trainer()
                .evaluations(),
            0
        );
    }

    #[test]
    fn training_counts_its_evaluations_in_the_state_while_the_swimmer_is_paused() {
        // As the page does it: an interactive frame budget, the learning lab,
        // the simulation paused, then Start training.
        let mut lab = Lab::new(Settings::default());
        lab.set_frame_budget(Some(INTERACTIVE_FRAME_BUDGET_SECS));
        let mut s = lab.settings().clone();
        s.scene = Scene::Learning;
        s.learning.annealing_steps = 200;
        s.paused = true;
        lab.apply_settings(s);
        let evaluations = |lab: &Lab| {
            crate::automation::StateReport::new(lab, "test", 60.0)
                .scene_report
                .learning
                .expect("the learning lab reports")
                .evaluations
        };
        assert_eq!(evaluations(&lab), 0);
        let mut s = lab.settings().clone();
        s.learning.training = true;
        lab.apply_settings(s);
        let mut counts = Vec::new();
        for frame in 1..=4 {
            lab.advance_frame(1.0 / 60.0, f64::from(frame) / 60.0);
            counts.push(evaluations(&lab));
        }
        assert!(
            counts.windows(2).all(|w| w[1] > w[0]) && counts[0] > 0,
            "evaluations after each frame: {counts:?}"
        );
        assert_eq!(lab.runs()[0].steps(), 0, "the swimmer stays paused");
        // Pause training: the count stays put.
        let mut s = lab.settings().clone();
        s.learning.training = false;
        lab.apply_settings(s);
        let before = evaluations(&lab);
        lab.advance_frame(1.0 / 60.0, 1.0);
        assert_eq!(evaluations(&lab), before);
    }

    #[test]
    fn a_turn_needs_the_physics_scene_and_a_selected_fish() {
        let mut boids = Lab::new(Settings::default());
        assert!(boids.turn_selected(30.0).is_err());
        let mut lab = physics_lab();
        let err = lab.turn_selected(30.0).unwrap_err().to_string();
        assert!(err.contains("select"), "{err}");
        let mut settings = lab.settings().clone();
        settings.physics.selected = Some(0);
        lab.apply_settings(settings);
        assert!(lab.turn_selected(f32::NAN).is_err());
        assert!(lab.turn_selected(500.0).is_err());
        lab.turn_selected(45.0).unwrap();
        lab.step(1);
        assert!(lab.runs()[0].scene().physics().unwrap().animals()[0].is_turning());
    }

    #[test]
    fn switching_scenes_changes_the_step_length() {
        let mut lab = Lab::new(Settings::default());
        assert!((lab.step_secs() - 1.0 / 60.0).abs() < 1e-9);
        let mut settings = lab.settings().clone();
        settings.scene = Scene::Physics;
        lab.apply_settings(settings.clone());
        assert!((lab.step_secs() - 0.055).abs() < 1e-6);
        lab.advance_frame(0.11, 0.0);
        assert_eq!(lab.runs()[0].steps(), 2);
        settings.scene = Scene::Boids;
        lab.apply_settings(settings);
        assert!(lab.runs()[0].scene().physics().is_none());
        lab.advance_frame(0.06, 0.1);
        assert_eq!(lab.runs()[0].steps(), 3, "a new run at 1/60 s per step");
    }
}
