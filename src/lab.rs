//! The running experiment: the simulated world, the teacher's settings and the clock
//! that advances one in fixed steps.
//!
//! `Lab` has no GPU and no UI, so everything the UI and the automation API can do to
//! a run is tested natively. The app owns one `Lab` and draws it.

use glam::Vec3;

use std::collections::VecDeque;

use crate::clock::{FixedStepClock, RateMeter};
use crate::metrics_history::{MetricsHistory, MetricsSample};
use crate::settings::physics::TURN_MAX_DEG;
use crate::settings::{Scene, Settings, Side};
use crate::sim::body::{MUSCLE_COUNT, NODE_COUNT};
use crate::sim::learning::learning_lab::LearningLab;
use crate::sim::learning::learning_lab::RaceNotReady;
use crate::sim::reef::report::ReefCensus;
use crate::sim::reef::world::ReefWorld;
use crate::sim::scene::{SceneWorld, centre};
use crate::sim::{HandCommand, PhysicsConfig, PhysicsWorld, World, WorldConfig};

mod skip;
pub use skip::{SKIP_FRAME_BUDGET_SECS, SKIP_LIMIT_SECS, SkipOutcome, SkipProgress};

/// Seconds of the selected fish's muscles and speed kept for the plots.
pub const BODY_TRACE_SECS: f64 = 10.0;

/// One step of the selected physical fish, for the muscle and speed plots.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodySample {
    pub time_secs: f64,
    /// Speed of the centre of mass, m/s.
    pub speed_m_per_s: f32,
    /// The 12 muscle contractions in [0, 1] (order of `body_layout::MUSCLES`).
    pub muscles: [f32; MUSCLE_COUNT],
}

/// One tank's run: its scene's world, what is needed to draw it smoothly, and its
/// metrics. Cloned to go back in time (*Skip to the moment*, `lab/skip.rs`).
#[derive(Clone)]
pub struct Run {
    side: Side,
    scene: SceneWorld,
    /// Every animal's position before the last step (see
    /// [`SceneWorld::positions_m`]), for interpolated drawing.
    previous_positions_m: Vec<Vec3>,
    /// Every animal's nodes before the last step (see [`SceneWorld::nodes_m`]).
    previous_nodes_m: Vec<[Vec3; NODE_COUNT]>,
    /// The selected physical fish's last seconds, and which fish it is.
    body_trace: VecDeque<BodySample>,
    traced: Option<u32>,
    history: MetricsHistory,
    /// The scene's counts at each metrics sample over the last
    /// [`crate::metrics_history::HISTORY_SECS`] (the reef; see
    /// [`SceneWorld::census`]), oldest first.
    census: VecDeque<ReefCensus>,
    /// Which rebuild of the lab made this world.
    generation: u64,
    /// The obstacles the settings asked for when last applied.
    obstacles_from_settings: Option<Vec<crate::sim::Obstacle>>,
    /// Obstacle changes since the world was built.
    obstacle_edits: u64,
}

impl Run {
    /// A run of `settings`' scene for tank `side`; the learning lab takes
    /// `learning` (kept while another scene was shown) if it fits the settings.
    fn new(
        side: Side,
        settings: &Settings,
        generation: u64,
        learning: &mut Option<LearningLab>,
    ) -> Self {
        let mut run = Self {
            side,
            scene: build_scene(settings, side, learning),
            previous_positions_m: Vec::new(),
            previous_nodes_m: Vec::new(),
            body_trace: VecDeque::new(),
            traced: None,
            history: MetricsHistory::default(),
            census: VecDeque::new(),
            generation,
            obstacles_from_settings: world_config(settings, side).obstacles,
            obstacle_edits: 0,
        };
        run.snapshot();
        run.follow(settings);
        run.sample_metrics();
        run
    }

    /// The simulated world of this tank.
    pub fn scene(&self) -> &SceneWorld {
        &self.scene
    }

    /// The boid world, in the aquarium and the schooling lab.
    pub fn boids(&self) -> Option<&World> {
        self.scene.boids()
    }

    /// The physical fish, in the physics scene.
    pub fn physics(&self) -> Option<&PhysicsWorld> {
        self.scene.physics()
    }

    /// The fish with minds, in the reef scene.
    pub fn reef(&self) -> Option<&ReefWorld> {
        self.scene.reef()
    }

    /// The learning lab, in its scene.
    pub fn learning(&self) -> Option<&LearningLab> {
        self.scene.learning()
    }

    /// Simulated seconds since the run began.
    pub fn time_secs(&self) -> f64 {
        self.scene.time_secs()
    }

    /// Steps since the run began.
    pub fn steps(&self) -> u64 {
        self.scene.steps()
    }

    /// Animals in the tank (eaten ones not counted).
    pub fn animal_count(&self) -> usize {
        self.scene.animal_count()
    }

    /// Where every animal's nodes should be drawn, by index: `alpha` of the way
    /// from their previous to their current positions (tank frame, metres; see
    /// [`SceneWorld::nodes_m`]).
    pub fn drawn_nodes_all_m(&self, alpha: f32) -> Vec<[Vec3; NODE_COUNT]> {
        let mut now = Vec::new();
        self.scene.nodes_m(&mut now);
        for (i, current) in now.iter_mut().enumerate() {
            if let Some(previous) = self.previous_nodes_m.get(i) {
                *current = std::array::from_fn(|k| previous[k].lerp(current[k], alpha));
            }
        }
        now
    }

    /// Where animal `index`'s nodes should be drawn (see
    /// [`Self::drawn_nodes_all_m`]; for one animal, not in a loop).
    pub fn drawn_nodes_m(&self, index: usize, alpha: f32) -> [Vec3; NODE_COUNT] {
        self.drawn_nodes_all_m(alpha)
            .get(index)
            .copied()
            .unwrap_or([Vec3::ZERO; NODE_COUNT])
    }

    /// Where every animal should be drawn, by index: `alpha` of the way from
    /// its previous to its current position (see [`SceneWorld::positions_m`]).
    pub fn drawn_positions_m(&self, alpha: f32) -> Vec<Vec3> {
        let mut now = Vec::new();
        self.scene.positions_m(&mut now);
        for (i, current) in now.iter_mut().enumerate() {
            if let Some(previous) = self.previous_positions_m.get(i) {
                *current = previous.lerp(*current, alpha);
            }
        }
        now
    }

    /// Where animal `index` should be drawn (see [`Self::drawn_positions_m`];
    /// for one animal, not in a loop).
    pub fn drawn_position_m(&self, index: usize, alpha: f32) -> Vec3 {
        self.drawn_positions_m(alpha)
            .get(index)
            .copied()
            .unwrap_or(Vec3::ZERO)
    }

    /// Every animal that can be selected: index, drawn centre (`alpha` of the
    /// way from the last step) and body length.
    pub fn selectable_animals(&self, alpha: f32) -> Vec<(usize, Vec3, f32)> {
        let positions = self.drawn_positions_m(alpha);
        let nodes = self.drawn_nodes_all_m(alpha);
        self.scene
            .pickable()
            .into_iter()
            .map(|(i, length)| {
                let c = if self.scene.has_body(i) {
                    centre(&nodes[i])
                } else {
                    positions[i]
                };
                (i, c, length)
            })
            .collect()
    }

    /// The selected physical fish's muscles and speed over the last
    /// [`BODY_TRACE_SECS`], oldest first.
    pub fn body_trace(&self) -> &VecDeque<BodySample> {
        &self.body_trace
    }

    pub fn side(&self) -> Side {
        self.side
    }

    /// Changes whenever the world is rebuilt (new seed, scene or reset) or its
    /// obstacles change, so the renderer knows when its static meshes are stale.
    pub fn generation(&self) -> u64 {
        (self.generation << 32) | (self.obstacle_edits & 0xFFFF_FFFF)
    }

    /// The metrics of the last minutes.
    pub fn history(&self) -> &MetricsHistory {
        &self.history
    }

    /// The reef's counts over the last minutes, one per metrics sample, oldest
    /// first (empty in the other scenes).
    pub fn census(&self) -> &VecDeque<ReefCensus> {
        &self.census
    }

    /// The latest metrics.
    pub fn metrics(&self) -> MetricsSample {
        self.history.latest().copied().unwrap_or_default()
    }

    fn step(&mut self, snapshot: bool) {
        if snapshot {
            self.snapshot();
        }
        self.scene.step();
        if let Some(fish) = self
            .traced
            .and_then(|i| self.scene.physical_fish(i as usize))
        {
            push_trace(
                &mut self.body_trace,
                sample_of(fish, self.scene.time_secs()),
            );
        }
        if self
            .scene
            .steps()
            .is_multiple_of(self.scene.sample_every_steps())
        {
            self.sample_metrics();
        }
    }

    /// Records the world's latest metrics (computed by the simulation every step).
    /// Force shares are over the last second, so a mode switch shows at once.
    fn sample_metrics(&mut self) {
        if let Some(census) = self.scene.census() {
            self.census.push_back(census);
            while self.census.front().is_some_and(|first| {
                census.time_secs - first.time_secs > crate::metrics_history::HISTORY_SECS
            }) {
                self.census.pop_front();
            }
        }
        let Some(m) = self.scene.metrics() else {
            return;
        };
        self.history.push(MetricsSample::new(
            m.time_secs,
            &m.school,
            m.force_frequencies,
            m.catches,
        ));
    }

    /// Remembers where every animal is, for interpolated drawing.
    fn snapshot(&mut self) {
        self.scene.positions_m(&mut self.previous_positions_m);
        self.scene.nodes_m(&mut self.previous_nodes_m);
    }

    /// Follows the physics scene's settings: counts, behaviour, current, the
    /// selected fish's hand command.
    fn follow_physics(physics: &mut PhysicsWorld, settings: &Settings) -> bool {
        let wanted = &settings.physics;
        let counts = (wanted.fish_count as usize, wanted.sharks as usize);
        let recount = counts != (physics.fish_count(), physics.shark_count());
        if recount {
            physics.set_counts(counts.0, counts.1);
        }
        if physics.behaviour() != wanted.behaviour {
            physics.set_behaviour(wanted.behaviour);
        }
        if physics.current().strength_m_per_s != wanted.current_m_per_s {
            physics.set_current(wanted.current_m_per_s);
        }
        let hand = wanted.selected.filter(|_| wanted.hand_control).map(|i| {
            (
                i as usize,
                HandCommand {
                    speed_fraction: wanted.hand_speed,
                    pitch_rad: wanted.hand_pitch_deg.to_radians(),
                },
            )
        });
        physics.set_hand_command(hand);
        recount
    }

    /// Starts a turn of `angle_deg` (+ left) on physical animal `index`.
    fn turn(&mut self, index: usize, angle_deg: f32) {
        if let SceneWorld::Physics(physics) = &mut self.scene {
            physics.turn(index, angle_deg);
        }
    }

    /// Follows the reef scene's live settings (water, minds).
    fn follow_reef(reef: &mut ReefWorld, settings: &Settings) {
        let wanted = &settings.reef;
        if reef.config().visibility_m != wanted.visibility_m {
            reef.set_visibility(wanted.visibility_m);
        }
        if reef.config().current_m_per_s != wanted.current_m_per_s {
            reef.set_current(wanted.current_m_per_s);
        }
        if reef.config().traits != wanted.traits {
            reef.set_traits(wanted.traits);
        }
    }

    /// Follows the schooling lab's settings for this tank: counts, boid layer,
    /// species and obstacles. Returns whether animals came or went.
    fn follow_boids(&mut self, settings: &Settings) -> bool {
        let SceneWorld::Boids(world) = &mut self.scene else {
            return false;
        };
        let mut recount = false;
        let tank = settings.tank(self.side);
        let fish_count = tank.fish_count as usize;
        if fish_count != world.fish().len() {
            world.set_fish_count(fish_count);
            recount = true;
        }
        let boids = boid_params(settings, self.side);
        if world.boids() != boids.as_ref() {
            world.set_boids(boids);
        }
        let config = world_config(settings, self.side);
        if (config.sharks, config.stingrays) != (world.sharks().len(), world.stingrays().len()) {
            world.set_species_counts(config.sharks, config.stingrays);
            recount = true;
        }
        if config.obstacles.as_ref() != self.obstacles_from_settings.as_ref() {
            world.set_obstacles(match &config.obstacles {
                Some(obstacles) => obstacles.clone(),
                // Back to the seed's layout.
                None => World::seeded_obstacles(config.seed),
            });
            self.obstacles_from_settings = config.obstacles;
            self.obstacle_edits += 1;
        }
        recount
    }

    /// Follows new settings for this tank without restarting where possible.
    fn follow(&mut self, settings: &Settings) {
        let (recount, selected) = match &mut self.scene {
            SceneWorld::Boids(_) => (self.follow_boids(settings), None),
            SceneWorld::Physics(physics) => (
                Self::follow_physics(physics, settings),
                settings.physics.selected,
            ),
            SceneWorld::Reef(reef) => {
                Self::follow_reef(reef, settings);
                (false, settings.reef.selected)
            }
            // The lab applies the learning settings itself.
            SceneWorld::Learning(_) => (false, None),
        };
        if recount {
            self.snapshot();
        }
        if self.traced != selected {
            self.traced = selected;
            self.body_trace.clear();
        }
    }
}

/// The world of `settings`' scene for tank `side`.
fn build_scene(settings: &Settings, side: Side, learning: &mut Option<LearningLab>) -> SceneWorld {
    match settings.scene {
        Scene::Aquarium | Scene::Boids => {
            let mut world = World::new(world_config(settings, side));
            world.set_boids(boid_params(settings, side));
            SceneWorld::Boids(Box::new(world))
        }
        Scene::Physics => SceneWorld::Physics(PhysicsWorld::new(physics_config(settings))),
        Scene::Reef => SceneWorld::Reef(ReefWorld::new(settings.reef.config(settings.seed))),
        Scene::Learning => {
            let wanted = &settings.learning;
            // The lab kept while another scene was shown, if it is the same
            // training.
            let kept = learning.take().filter(|l| {
                l.species() == wanted.species
                    && l.annealing_steps() == u64::from(wanted.annealing_steps)
                    && l.seed() == settings.seed
            });
            let mut learning = kept.unwrap_or_else(|| {
                // Open water for the learners: no rocks.
                LearningLab::new(
                    wanted.species,
                    u64::from(wanted.annealing_steps),
                    settings.seed,
                    wanted.controller,
                    &crate::sim::Tank::default(),
                )
            });
            if learning.controller() != wanted.controller {
                learning.set_controller(wanted.controller);
            }
            SceneWorld::Learning(Box::new(learning))
        }
    }
}

/// The selected physical fish's speed and muscles now.
fn sample_of(animal: &crate::sim::PhysicalFish, time_secs: f64) -> BodySample {
    BodySample {
        time_secs,
        speed_m_per_s: animal.point.velocity_m_per_s.length(),
        muscles: animal.motor().muscles,
    }
}

/// Appends `sample`, keeping the last [`BODY_TRACE_SECS`].
fn push_trace(trace: &mut VecDeque<BodySample>, sample: BodySample) {
    trace.push_back(sample);
    while trace
        .front()
        .is_some_and(|s| s.time_secs < sample.time_secs - BODY_TRACE_SECS)
    {
        trace.pop_front();
    }
}

/// Why the lab refused a command (`shoal.turn`, `shoal.train`, `shoal.race`).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LabError {
    /// The command (named without its parentheses) needs the learning lab.
    #[error("{0}() works in the learning lab only")]
    LearningLabOnly(&'static str),
    #[error("turn() works in the physics fish scene only")]
    PhysicsSceneOnly,
    #[error("turn(): select a fish first (physics.selected)")]
    NoFishSelected,
    #[error("turn(): {0} is out of range: choose from -{TURN_MAX_DEG} to {TURN_MAX_DEG} degrees")]
    TurnOutOfRange(f32),
    #[error(transparent)]
    RaceNotReady(#[from] RaceNotReady),
    #[error("skip(): this scene has no moment to skip to (the reef's demos have)")]
    NoMoment,
}

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

    /// The left (or only) tank's boid world, in the aquarium and the schooling
    /// lab.
    pub fn boids(&self) -> Option<&World> {
        self.runs[0].boids()
    }

    /// The left (or only) tank's learning lab, for the app's actions (race,
    /// save, load) and training.
    pub fn learning_mut(&mut self) -> Option<&mut LearningLab> {
        match &mut self.runs[0].scene {
            SceneWorld::Learning(l) => Some(l),
            _ => None,
        }
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
        self.settings.scene == Scene::Boids && self.settings.compare
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
            || before.learning.training_key() != self.settings.learning.training_key()
            || (self.settings.scene == Scene::Reef
                && before.reef.rebuild_key() != self.settings.reef.rebuild_key())
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
        if self.comparing() { 2 } else { 1 }
    }

    fn rebuild(&mut self) {
        self.skip = None;
        self.skip_outcome = None;
        let mut learning = self.parked_learning.take();
        for run in std::mem::take(&mut self.runs) {
            if let SceneWorld::Learning(l) = run.scene {
                learning = Some(*l);
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
        if self.settings.scene == Scene::Learning {
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
        /// Steps per frame without a budget (see [`FixedStepClock`]).
        const MAX_STEPS: u32 = 32;
        self.clock.max_steps_per_frame = match self.frame_budget_secs {
            Some(budget) if self.step_cost_secs > 0.0 => {
                ((budget / self.step_cost_secs).floor() as u32).clamp(1, MAX_STEPS)
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
            // Smoothed over a few frames; the first measurement is taken as is.
            self.step_cost_secs = if self.step_cost_secs > 0.0 {
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
        if self.settings.scene != Scene::Physics {
            return Err(LabError::PhysicsSceneOnly);
        }
        let Some(selected) = self.settings.physics.selected else {
            return Err(LabError::NoFishSelected);
        };
        if !angle_deg.is_finite() || angle_deg.abs() > TURN_MAX_DEG {
            return Err(LabError::TurnOutOfRange(angle_deg));
        }
        self.runs[0].turn(selected as usize, angle_deg);
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

fn physics_config(settings: &Settings) -> PhysicsConfig {
    let physics = &settings.physics;
    PhysicsConfig {
        seed: settings.seed,
        fish_count: physics.fish_count as usize,
        sharks: physics.sharks as usize,
        behaviour: physics.behaviour,
        current_m_per_s: physics.current_m_per_s,
        // The seed's rocks, as the schooling lab's tank has them.
        obstacles: World::seeded_obstacles(settings.seed),
    }
}

fn world_config(settings: &Settings, side: Side) -> WorldConfig {
    let tank = settings.tank(side);
    let boids = settings.scene == Scene::Boids;
    WorldConfig {
        seed: settings.seed,
        // The aquarium and the schooling lab (other scenes build no boid world).
        fish_count: if matches!(settings.scene, Scene::Aquarium | Scene::Boids) {
            tank.fish_count as usize
        } else {
            0
        },
        // Predators, stingrays and edited rocks belong to the schooling lab.
        sharks: if boids { tank.sharks as usize } else { 0 },
        stingrays: if boids { tank.stingrays as usize } else { 0 },
        obstacles: if boids { tank.obstacles.clone() } else { None },
    }
}

fn boid_params(settings: &Settings, side: Side) -> Option<crate::sim::BoidParams> {
    (settings.scene == Scene::Boids).then(|| settings.tank(side).boid_params())
}

#[cfg(test)]
mod tests {
    use super::*;

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
        lab.boids()
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
        assert_eq!(lab.boids().unwrap().steps(), 0);
        lab.step(3);
        assert_eq!(lab.boids().unwrap().steps(), 3);
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
        assert_eq!(b.boids().unwrap().steps(), 0, "a new seed starts a new run");
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
        assert_eq!(lab.boids().unwrap().fish().len(), 37);
        assert_eq!(lab.boids().unwrap().steps(), 10);
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
            (14..=15).contains(&slow.boids().unwrap().steps()),
            "{}",
            slow.boids().unwrap().steps()
        );
        assert!(
            (479..=480).contains(&fast.boids().unwrap().steps()),
            "{}",
            fast.boids().unwrap().steps()
        );
    }

    #[test]
    fn drawn_positions_lie_between_the_last_two_states() {
        let mut lab = Lab::new(Settings::default());
        lab.advance_frame(1.5 / 60.0, 0.0);
        let alpha = lab.clock.alpha();
        assert!(alpha > 0.0 && alpha < 1.0);
        for (i, fish) in lab.boids().unwrap().fish().iter().enumerate() {
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
        assert_eq!(run.physics().unwrap().animals().len(), 5);
        assert!(lab.boids().is_none(), "no boids in the physics tank");
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
        let physics = lab.runs()[0].physics().unwrap();
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
        let now = run.physics().unwrap().animals()[2].nodes_m();
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
        let reef = lab.runs()[0].reef().expect("a reef");
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
        let reef = lab.runs()[0].reef().unwrap();
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
        let reef = lab.runs()[0].reef().unwrap();
        assert_eq!(lab.runs()[0].steps(), 0);
        assert_eq!(reef.animals().len(), 3);
        let mut s = lab.settings().clone();
        s.reef.demo = ReefScene::PredatorAndSchool;
        s.reef.prey_count = Some(30);
        lab.apply_settings(s);
        assert_eq!(lab.runs()[0].reef().unwrap().animals().len(), 31);
        // Drawn positions of point-mass fish lie between the last two states.
        lab.step(3);
        let run = &lab.runs()[0];
        for (i, c, _) in run.selectable_animals(0.5) {
            let now = run.reef().unwrap().animals()[i].body.position_m();
            assert!(c.distance(now) < 0.1);
        }
    }

    #[test]
    fn the_learning_lab_trains_on_request_and_keeps_its_progress_across_scenes() {
        let mut settings = Settings {
            scene: Scene::Learning,
            ..Settings::default()
        };
        settings.learning.annealing_steps = 90;
        let mut lab = Lab::new(settings);
        assert!(lab.boids().is_none() && lab.scene().obstacles().is_empty());
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
            lab.runs()[0].learning().unwrap().trainer().evaluations(),
            30
        );
        // Training runs a little each frame while it is on.
        let mut s = lab.settings().clone();
        s.learning.training = true;
        lab.apply_settings(s);
        lab.advance_frame(0.1, 0.1);
        lab.advance_frame(0.1, 0.2);
        assert!(lab.runs()[0].learning().unwrap().trainer().evaluations() > 30);
        // Settings that change nothing here (the controller, the speed, the
        // boid tank's fish) leave the water open: no aquarium fish, no rocks.
        let mut s = lab.settings().clone();
        s.learning.controller = crate::sim::learning::learning_lab::ControllerChoice::HandTuned;
        s.speed = 2.0;
        s.left.fish_count = 500;
        lab.apply_settings(s);
        assert!(lab.boids().is_none() && lab.scene().obstacles().is_empty());
        // A different length, or Reset training, starts from a brain-dead fish.
        lab.reset_training();
        assert_eq!(lab.runs()[0].learning().unwrap().trainer().evaluations(), 0);
        let mut s = lab.settings().clone();
        s.learning.annealing_steps = 120;
        lab.train(5).unwrap();
        lab.apply_settings(s);
        assert_eq!(lab.runs()[0].learning().unwrap().annealing_steps(), 120);
        assert_eq!(lab.runs()[0].learning().unwrap().trainer().evaluations(), 0);
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
        assert!(lab.runs()[0].physics().unwrap().animals()[0].is_turning());
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
        assert!(lab.runs()[0].physics().is_none());
        lab.advance_frame(0.06, 0.1);
        assert_eq!(lab.runs()[0].steps(), 3, "a new run at 1/60 s per step");
    }
}
