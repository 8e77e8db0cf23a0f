//! The running experiment: the simulated world, the teacher's settings and the clock
//! that advances one in fixed steps.
//!
//! `Lab` has no GPU and no UI, so everything the UI and the automation API can do to
//! a run is tested natively. The app owns one `Lab` and draws it.

use glam::Vec3;

use std::collections::VecDeque;

use crate::clock::{FixedStepClock, RateMeter};
use crate::metrics_history::{MetricsHistory, MetricsSample, SAMPLE_EVERY_STEPS};
use crate::settings::{Scene, Settings, Side};
use crate::sim::body::{MUSCLE_COUNT, NODE_COUNT};
use crate::sim::learning::learning_lab::LearningLab;
use crate::sim::reef_world::{ReefBody, ReefWorld};
use crate::sim::{HandCommand, PhysicsConfig, PhysicsWorld, World, WorldConfig};

/// Physics steps between two metrics samples: 5 × 0.055 s = 0.275 s, about the
/// boid scenes' 15 × 1/60 s.
const PHYSICS_SAMPLE_EVERY_STEPS: u64 = 5;

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

/// One tank's run: its world, what is needed to draw it smoothly, and its metrics.
pub struct Run {
    side: Side,
    /// The boid world; in the physics scene it holds only the tank and its rocks.
    world: World,
    /// The muscle-driven fish of the physics scene.
    physics: Option<PhysicsWorld>,
    /// The fish with minds of the reef scene.
    reef: Option<ReefWorld>,
    /// The learning lab's training, demo fish and race (kept by the `Lab` while
    /// another scene is shown, so progress survives a visit elsewhere).
    learning: Option<LearningLab>,
    /// Node positions of every physical animal before the last step.
    previous_nodes_m: Vec<[Vec3; NODE_COUNT]>,
    /// The selected physical fish's last seconds, and which fish it is.
    body_trace: VecDeque<BodySample>,
    traced: Option<u32>,
    /// Fish positions before the last step, for interpolated drawing.
    previous_positions_m: Vec<Vec3>,
    history: MetricsHistory,
    /// Which rebuild of the lab made this world.
    generation: u64,
    /// The obstacles the settings asked for when last applied.
    obstacles_from_settings: Option<Vec<crate::sim::Obstacle>>,
    /// Obstacle changes since the world was built.
    obstacle_edits: u64,
}

impl Run {
    fn new(side: Side, settings: &Settings, generation: u64) -> Self {
        let mut world = World::new(world_config(settings, side));
        world.set_boids(boid_params(settings, side));
        let physics = (settings.scene == Scene::Physics)
            .then(|| PhysicsWorld::new(physics_config(settings, world.obstacles())));
        let reef = (settings.scene == Scene::Reef)
            .then(|| ReefWorld::new(settings.reef.config(settings.seed)));
        if let Some(reef) = &reef {
            // The boid world only holds the tank and the reef's rocks, for drawing.
            world.set_obstacles(reef.obstacles().to_vec());
        }
        if settings.scene == Scene::Learning {
            // Open water for the learners: no rocks.
            world.set_obstacles(Vec::new());
        }
        let mut run = Self {
            side,
            world,
            physics,
            reef,
            learning: None,
            previous_nodes_m: Vec::new(),
            body_trace: VecDeque::new(),
            traced: None,
            previous_positions_m: Vec::new(),
            history: MetricsHistory::default(),
            generation,
            obstacles_from_settings: settings.tank(side).obstacles.clone(),
            obstacle_edits: 0,
        };
        run.snapshot_positions();
        run.follow_physics(settings);
        run.follow_reef(settings);
        run.sample_metrics();
        run
    }

    /// The physical fish, in the physics scene.
    pub fn physics(&self) -> Option<&PhysicsWorld> {
        self.physics.as_ref()
    }

    /// The fish with minds, in the reef scene.
    pub fn reef(&self) -> Option<&ReefWorld> {
        self.reef.as_ref()
    }

    /// The learning lab, in its scene.
    pub fn learning(&self) -> Option<&LearningLab> {
        self.learning.as_ref()
    }

    /// The muscle bodies of the learning scene (the demo fish, then the racing
    /// sharks) now, tank frame.
    fn learning_nodes(&self) -> Vec<[Vec3; NODE_COUNT]> {
        self.learning.as_ref().map_or_else(Vec::new, |l| {
            std::iter::once(l.demo_nodes_m())
                .chain(l.race_nodes_m().into_iter().map(|(_, n)| n))
                .collect()
        })
    }

    /// Simulated seconds since the run began.
    pub fn time_secs(&self) -> f64 {
        if self.learning.is_some() {
            return self.steps() as f64 * step_secs(Scene::Learning);
        }
        match (&self.physics, &self.reef) {
            (Some(physics), _) => physics.time_secs(),
            (_, Some(reef)) => reef.time_secs(),
            _ => self.world.time_secs(),
        }
    }

    /// Steps since the run began.
    pub fn steps(&self) -> u64 {
        if let Some(l) = &self.learning {
            return l.demo_steps();
        }
        match (&self.physics, &self.reef) {
            (Some(physics), _) => physics.steps(),
            (_, Some(reef)) => reef.steps(),
            _ => self.world.steps(),
        }
    }

    /// Animals in the tank: fish (boids, physical or with minds; eaten ones
    /// not counted), sharks and stingrays.
    pub fn animal_count(&self) -> usize {
        match (&self.physics, &self.reef) {
            (Some(physics), _) => physics.animals().len(),
            (_, Some(reef)) => reef.alive_count(),
            _ => self.world.fish().len() + self.world.sharks().len() + self.world.stingrays().len(),
        }
    }

    /// The nodes of muscle-driven animal `index` (physics scene, or a reef
    /// animal with the muscle body).
    fn nodes_now(&self, index: usize) -> Option<[Vec3; NODE_COUNT]> {
        if self.learning.is_some() {
            return self.learning_nodes().get(index).copied();
        }
        if let Some(physics) = &self.physics {
            return physics.animals().get(index).map(|a| a.nodes_m());
        }
        match self.reef.as_ref()?.animals().get(index).map(|a| &a.body) {
            Some(ReefBody::Physical(p)) => Some(p.nodes_m()),
            _ => None,
        }
    }

    /// Where physical animal `index`'s nodes should be drawn: `alpha` of the way
    /// from their previous to their current positions (tank frame, metres).
    pub fn drawn_nodes_m(&self, index: usize, alpha: f32) -> [Vec3; NODE_COUNT] {
        let Some(current) = self.nodes_now(index) else {
            return [Vec3::ZERO; NODE_COUNT];
        };
        match self.previous_nodes_m.get(index) {
            Some(previous) => std::array::from_fn(|k| previous[k].lerp(current[k], alpha)),
            None => current,
        }
    }

    /// Every animal that can be selected (physics scene; living reef animals):
    /// index, drawn centre (`alpha` of the way from the last step) and body
    /// length.
    pub fn selectable_animals(&self, alpha: f32) -> Vec<(usize, Vec3, f32)> {
        let centre = |nodes: [Vec3; NODE_COUNT]| nodes.iter().sum::<Vec3>() / NODE_COUNT as f32;
        if let Some(physics) = &self.physics {
            return physics
                .animals()
                .iter()
                .enumerate()
                .map(|(i, a)| (i, centre(self.drawn_nodes_m(i, alpha)), a.body_length_m()))
                .collect();
        }
        let Some(reef) = &self.reef else {
            return Vec::new();
        };
        reef.animals()
            .iter()
            .enumerate()
            .filter(|(_, a)| a.alive)
            .map(|(i, a)| {
                let c = match &a.body {
                    ReefBody::Physical(_) => centre(self.drawn_nodes_m(i, alpha)),
                    ReefBody::Point(_) => self.drawn_reef_m(i, alpha),
                };
                (i, c, a.body.body_length_m())
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

    pub fn world(&self) -> &World {
        &self.world
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

    /// The latest metrics.
    pub fn metrics(&self) -> MetricsSample {
        self.history.latest().copied().unwrap_or_default()
    }

    fn step(&mut self, snapshot: bool) {
        if self.learning.is_some() {
            if snapshot {
                self.previous_nodes_m = self.learning_nodes();
            }
            if let Some(learning) = &mut self.learning {
                learning.step();
            }
            return;
        }
        if let Some(reef) = &mut self.reef {
            if snapshot {
                self.previous_nodes_m.clear();
                self.previous_positions_m.clear();
                for a in reef.animals() {
                    self.previous_positions_m.push(a.body.position_m());
                    if let ReefBody::Physical(p) = &a.body {
                        self.previous_nodes_m.push(p.nodes_m());
                    } else {
                        self.previous_nodes_m
                            .push([a.body.position_m(); NODE_COUNT]);
                    }
                }
            }
            reef.step();
            if let Some(ReefBody::Physical(p)) = self
                .traced
                .and_then(|i| reef.animals().get(i as usize))
                .map(|a| &a.body)
            {
                push_trace(&mut self.body_trace, sample_of(p, reef.time_secs()));
            }
            if reef.steps().is_multiple_of(PHYSICS_SAMPLE_EVERY_STEPS) {
                self.sample_metrics();
            }
            return;
        }
        if let Some(physics) = &mut self.physics {
            if snapshot {
                self.previous_nodes_m.clear();
                self.previous_nodes_m
                    .extend(physics.animals().iter().map(|a| a.nodes_m()));
            }
            physics.step();
            if let Some(animal) = self.traced.and_then(|i| physics.animals().get(i as usize)) {
                push_trace(&mut self.body_trace, sample_of(animal, physics.time_secs()));
            }
            if physics.steps().is_multiple_of(PHYSICS_SAMPLE_EVERY_STEPS) {
                self.sample_metrics();
            }
            return;
        }
        if snapshot {
            self.snapshot_positions();
        }
        self.world.step();
        if self.world.steps().is_multiple_of(SAMPLE_EVERY_STEPS) {
            self.sample_metrics();
        }
    }

    /// Records the world's latest metrics (computed by the simulation every step).
    /// Force shares are over the last second, so a mode switch shows at once.
    fn sample_metrics(&mut self) {
        if let Some(reef) = &self.reef {
            self.history.push(MetricsSample::new(
                reef.time_secs(),
                &reef.school_metrics(),
                [0.0; 5],
                u64::from(reef.counts().prey_eaten),
            ));
            return;
        }
        if let Some(physics) = &self.physics {
            self.history.push(MetricsSample::new(
                physics.time_secs(),
                &physics.school_metrics(),
                [0.0; 5],
                0,
            ));
            return;
        }
        let metrics = self.world.metrics();
        let force_frequencies = if self.world.boids().is_some() {
            metrics.force_frequencies_recent
        } else {
            [0.0; 5]
        };
        self.history.push(MetricsSample::new(
            self.world.time_secs(),
            &metrics.school,
            force_frequencies,
            metrics.catches,
        ));
    }

    /// Remembers where every animal is (fish, then sharks, then stingrays).
    fn snapshot_positions(&mut self) {
        self.previous_positions_m.clear();
        let world = &self.world;
        self.previous_positions_m.extend(
            world
                .fish()
                .iter()
                .chain(world.sharks().iter().map(|s| &s.body))
                .chain(world.stingrays().iter().map(|r| &r.body))
                .map(|f| f.position_m),
        );
    }

    fn interpolated(&self, slot: usize, current: Vec3, alpha: f32) -> Vec3 {
        match self.previous_positions_m.get(slot) {
            Some(previous) => previous.lerp(current, alpha),
            None => current,
        }
    }

    /// Where fish `index` should be drawn: `alpha` of the way from its previous to
    /// its current simulated position.
    pub fn drawn_position_m(&self, index: usize, alpha: f32) -> Vec3 {
        self.interpolated(index, self.world.fish()[index].position_m, alpha)
    }

    /// Where reef animal `index`'s centre should be drawn (see
    /// [`Self::drawn_position_m`]).
    pub fn drawn_reef_m(&self, index: usize, alpha: f32) -> Vec3 {
        match self.reef.as_ref().and_then(|r| r.animals().get(index)) {
            Some(a) => self.interpolated(index, a.body.position_m(), alpha),
            None => Vec3::ZERO,
        }
    }

    /// Where shark `index` should be drawn (see [`Self::drawn_position_m`]).
    pub fn drawn_shark_m(&self, index: usize, alpha: f32) -> Vec3 {
        let slot = self.world.fish().len() + index;
        self.interpolated(slot, self.world.sharks()[index].body.position_m, alpha)
    }

    /// Where stingray `index` should be drawn (see [`Self::drawn_position_m`]).
    pub fn drawn_stingray_m(&self, index: usize, alpha: f32) -> Vec3 {
        let slot = self.world.fish().len() + self.world.sharks().len() + index;
        self.interpolated(slot, self.world.stingrays()[index].body.position_m, alpha)
    }

    /// Follows the physics scene's settings: counts, behaviour, current, the
    /// selected fish's hand command and its trace.
    fn follow_physics(&mut self, settings: &Settings) {
        let Some(physics) = &mut self.physics else {
            return;
        };
        let wanted = &settings.physics;
        let counts = (wanted.fish_count as usize, wanted.sharks as usize);
        if counts != (physics.fish_count(), physics.shark_count()) {
            physics.set_counts(counts.0, counts.1);
            self.previous_nodes_m.clear();
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
        if self.traced != wanted.selected {
            self.traced = wanted.selected;
            self.body_trace.clear();
        }
    }

    /// Starts a turn of `angle_deg` (+ left) on physical animal `index`.
    fn turn(&mut self, index: usize, angle_deg: f32) {
        if let Some(physics) = &mut self.physics {
            physics.turn(index, angle_deg);
        }
    }

    /// Follows the reef scene's live settings (water) and the selected fish.
    fn follow_reef(&mut self, settings: &Settings) {
        let Some(reef) = &mut self.reef else {
            return;
        };
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
        if self.traced != wanted.selected {
            self.traced = wanted.selected;
            self.body_trace.clear();
        }
    }

    /// Follows new settings for this tank without restarting where possible.
    fn follow(&mut self, settings: &Settings) {
        if self.learning.is_some() {
            // The lab applies the learning settings itself; the boid world
            // stays empty open water.
            return;
        }
        if self.reef.is_some() {
            self.follow_reef(settings);
            return;
        }
        if self.physics.is_some() {
            self.follow_physics(settings);
            return;
        }
        let tank = settings.tank(self.side);
        let fish_count = tank.fish_count as usize;
        if fish_count != self.world.fish().len() {
            self.world.set_fish_count(fish_count);
            self.snapshot_positions();
        }
        let boids = boid_params(settings, self.side);
        if self.world.boids() != boids.as_ref() {
            self.world.set_boids(boids);
        }
        let config = world_config(settings, self.side);
        if (config.sharks, config.stingrays)
            != (self.world.sharks().len(), self.world.stingrays().len())
        {
            self.world
                .set_species_counts(config.sharks, config.stingrays);
            self.snapshot_positions();
        }
        if config.obstacles.as_ref() != self.obstacles_from_settings.as_ref() {
            match &config.obstacles {
                Some(obstacles) => self.world.set_obstacles(obstacles.clone()),
                // Back to the seed's layout: the obstacles are placed first from
                // the seed, so an empty world of the same seed has the same ones.
                None => {
                    let seeded = World::new(WorldConfig {
                        fish_count: 0,
                        sharks: 0,
                        stingrays: 0,
                        ..config.clone()
                    });
                    self.world.set_obstacles(seeded.obstacles().to_vec());
                }
            }
            self.obstacles_from_settings = config.obstacles;
            self.obstacle_edits += 1;
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
        let scene = settings.scene;
        let mut lab = Self {
            settings,
            clock: FixedStepClock::new(step_secs(scene)),
            runs: Vec::new(),
            steps_meter: RateMeter::default(),
            rebuilds: 0,
            frame_budget_secs: None,
            step_cost_secs: 0.0,
            parked_learning: None,
            evaluation_cost_secs: 0.0,
        };
        lab.rebuild();
        lab
    }

    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The left (or only) tank's world.
    pub fn world(&self) -> &World {
        &self.runs[0].world
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
        if self.settings.scene == Scene::Learning
            && before.learning.controller != self.settings.learning.controller
            && let Some(l) = self.runs[0].learning.as_mut()
        {
            l.set_controller(self.settings.learning.controller);
        }
        let rebuild = before.seed != self.settings.seed
            || before.scene != self.settings.scene
            || before.learning.training_key() != self.settings.learning.training_key()
            || (self.settings.scene == Scene::Reef
                && before.reef.rebuild_key() != self.settings.reef.rebuild_key())
            || self.runs.len() != self.wanted_runs();
        let unpaused = before.paused && !self.settings.paused;
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
        if let Some(l) = self.runs.first_mut().and_then(|r| r.learning.take()) {
            self.parked_learning = Some(l);
        }
        let max_steps = self.clock.max_steps_per_frame;
        self.clock = FixedStepClock::new(step_secs(self.settings.scene));
        self.clock.max_steps_per_frame = max_steps;
        self.step_cost_secs = 0.0;
        self.runs = Side::BOTH[..self.wanted_runs()]
            .iter()
            .map(|&side| {
                self.rebuilds += 1;
                Run::new(side, &self.settings, self.rebuilds)
            })
            .collect();
        if self.settings.scene == Scene::Learning {
            let wanted = &self.settings.learning;
            let keep = self.parked_learning.take().filter(|l| {
                l.species() == wanted.species
                    && l.annealing_steps() == u64::from(wanted.annealing_steps)
                    && l.seed() == self.settings.seed
            });
            let mut learning = keep.unwrap_or_else(|| {
                LearningLab::new(
                    wanted.species,
                    u64::from(wanted.annealing_steps),
                    self.settings.seed,
                    wanted.controller,
                    self.runs[0].world.tank(),
                )
            });
            if learning.controller() != wanted.controller {
                learning.set_controller(wanted.controller);
            }
            self.runs[0].learning = Some(learning);
        }
        self.clock.clear();
    }

    /// Runs `n` annealing evaluations of the learning lab now (`shoal.train(n)`).
    pub fn train(&mut self, n: u32) -> Result<u32, String> {
        let Some(l) = self.runs[0].learning.as_mut() else {
            return Err("train() works in the learning lab only".to_owned());
        };
        Ok(l.train(n as usize) as u32)
    }

    /// Starts the learning lab's training again from a brain-dead fish.
    pub fn reset_training(&mut self) {
        if self.settings.scene == Scene::Learning {
            self.parked_learning = None;
            self.runs[0].learning = None;
            self.rebuild();
        }
    }

    /// The learning lab, for the app's actions (race, save, load).
    pub fn learning_mut(&mut self) -> Option<&mut LearningLab> {
        self.runs[0].learning.as_mut()
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
        let Some(l) = self.runs[0].learning.as_mut() else {
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
    pub fn turn_selected(&mut self, angle_deg: f32) -> Result<(), String> {
        if self.settings.scene != Scene::Physics {
            return Err("turn() works in the physics fish scene only".to_owned());
        }
        let Some(selected) = self.settings.physics.selected else {
            return Err("turn(): select a fish first (physics.selected)".to_owned());
        };
        if !angle_deg.is_finite() || angle_deg.abs() > crate::physics_settings::TURN_MAX_DEG {
            return Err(format!(
                "turn(): {angle_deg} is out of range: choose from -{0} to {0} degrees",
                crate::physics_settings::TURN_MAX_DEG
            ));
        }
        self.runs[0].turn(selected as usize, angle_deg);
        Ok(())
    }

    /// Length of one simulation step of the current scene, seconds.
    pub fn step_secs(&self) -> f64 {
        step_secs(self.settings.scene)
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

    /// Did the last frame hit the step cap (the machine cannot keep up)?
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

/// Length of one simulation step, seconds: the fish world's 0.055 s
/// (`sim::paper_time::FISH_STEP_SECS`) for physical fish, the reef and the
/// learning lab, 1/60 s for boids.
fn step_secs(scene: Scene) -> f64 {
    match scene {
        Scene::Physics => f64::from(crate::sim::body::BodyParams::default().dt_secs),
        Scene::Reef => f64::from(crate::sim::reef_world::POINT_BODY_DT_SECS),
        Scene::Learning => f64::from(crate::sim::body::BodyParams::default().dt_secs),
        Scene::Aquarium | Scene::Boids => f64::from(World::DT_SECS),
    }
}

fn physics_config(settings: &Settings, obstacles: &[crate::sim::Obstacle]) -> PhysicsConfig {
    let physics = &settings.physics;
    PhysicsConfig {
        seed: settings.seed,
        fish_count: physics.fish_count as usize,
        sharks: physics.sharks as usize,
        behaviour: physics.behaviour,
        current_m_per_s: physics.current_m_per_s,
        obstacles: obstacles.to_vec(),
    }
}

fn world_config(settings: &Settings, side: Side) -> WorldConfig {
    let tank = settings.tank(side);
    let boids = settings.scene == Scene::Boids;
    WorldConfig {
        seed: settings.seed,
        // In the other scenes the boid world only holds the tank and its rocks.
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

    fn positions(lab: &Lab) -> Vec<Vec3> {
        lab.world().fish().iter().map(|f| f.position_m).collect()
    }

    #[test]
    fn paused_lab_does_not_advance_but_single_step_does() {
        let mut lab = Lab::new(Settings {
            paused: true,
            ..Settings::default()
        });
        assert_eq!(lab.advance_frame(0.1, 0.1), 0);
        assert_eq!(lab.world().steps(), 0);
        lab.step(3);
        assert_eq!(lab.world().steps(), 3);
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
        assert_eq!(b.world().steps(), 0, "a new seed starts a new run");
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
        assert_eq!(lab.world().fish().len(), 37);
        assert_eq!(lab.world().steps(), 10);
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
            (14..=15).contains(&slow.world().steps()),
            "{}",
            slow.world().steps()
        );
        assert!(
            (479..=480).contains(&fast.world().steps()),
            "{}",
            fast.world().steps()
        );
    }

    #[test]
    fn drawn_positions_lie_between_the_last_two_states() {
        let mut lab = Lab::new(Settings::default());
        lab.advance_frame(1.5 / 60.0, 0.0);
        let alpha = lab.clock.alpha();
        assert!(alpha > 0.0 && alpha < 1.0);
        for (i, fish) in lab.world().fish().iter().enumerate() {
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
        assert!(
            lab.world().fish().is_empty(),
            "no boids in the physics tank"
        );
        assert!(
            !lab.world().obstacles().is_empty(),
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
        use crate::sim::reef_world::{ReefBodyKind, ReefScene};
        let settings = Settings {
            scene: Scene::Reef,
            ..Settings::default()
        };
        let mut lab = Lab::new(settings);
        let reef = lab.runs()[0].reef().expect("a reef");
        assert_eq!(reef.config().scene, ReefScene::Reef);
        assert_eq!(
            lab.world().obstacles(),
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
                a.habits.kind == crate::sim::mind::FishKind::Predator
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
        assert!(lab.world().fish().is_empty() && lab.world().obstacles().is_empty());
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
        assert!(lab.world().fish().is_empty() && lab.world().obstacles().is_empty());
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
        let err = lab.turn_selected(30.0).unwrap_err();
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
